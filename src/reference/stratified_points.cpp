#include "reference/stratified_points.h"

#include <glm/geometric.hpp>

namespace ncube::reference {

std::uint64_t SampleStream::next_bits() {
  std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

std::uint64_t mix_seed(std::uint64_t a, std::uint64_t b, std::uint64_t c) {
  SampleStream stream(a * 0x9e3779b97f4a7c15ULL ^ (b + 0x632be59bd9b4e019ULL));
  const std::uint64_t first = stream.next_bits();
  SampleStream second(first ^ (c * 0xd1b54a32d192ed03ULL + 0x8cb92ba72f3d8dd7ULL));
  return second.next_bits();
}

std::vector<AreaSample> stratified_points(const Polygon& polygon, int side, std::uint64_t seed) {
  // The bilinear map v0 (0,0), v1 (1,0), v2 (1,1), v3 (0,1); a triangle is (v0, v1, v2, v2).
  const Vec3& v0 = polygon[0];
  const Vec3& v1 = polygon[1];
  const Vec3& v2 = polygon[2];
  const Vec3& v3 = polygon.count == 4 ? polygon[3] : polygon[2];
  SampleStream stream(seed);
  std::vector<AreaSample> samples;
  samples.reserve(std::size_t(side) * std::size_t(side));
  for (int b = 0; b < side; ++b)
    for (int a = 0; a < side; ++a) {
      const double u = (a + stream.next_unit()) / side;
      const double v = (b + stream.next_unit()) / side;
      const Vec3 du = (1.0 - v) * (v1 - v0) + v * (v2 - v3);
      const Vec3 dv = (1.0 - u) * (v3 - v0) + u * (v2 - v1);
      const Vec3 point = (1.0 - v) * ((1.0 - u) * v0 + u * v1) + v * ((1.0 - u) * v3 + u * v2);
      samples.push_back({point, glm::length(glm::cross(du, dv))});
    }
  return samples;
}

}  // namespace ncube::reference

#include "visibility/shooter.h"

#include <cmath>
#include <glm/geometric.hpp>

namespace ncube {

bool is_valid_part_count(int samples) {
  if (samples < 1 || samples > kMaxShooterParts) return false;
  const int k = int(std::lround(std::sqrt(double(samples))));
  return k * k == samples;
}

Shooter make_shooter(const Scene& scene, int patch, const Rgb& unshot, int samples) {
  const Patch& p = scene.patches[patch];
  Shooter s;
  s.patch = patch;
  s.polygon = p.polygon;
  s.normal = p.normal;
  s.unshot = unshot;
  const int k = int(std::lround(std::sqrt(double(samples))));
  s.part_count = k * k;
  s.side = k;
  for (int j = 0; j <= k; ++j)
    for (int i = 0; i <= k; ++i)
      s.grid[j * (k + 1) + i] = p.polygon.count == 3 && j == k
                                    ? p.polygon[2]
                                    : bilinear_point(p.polygon, double(i) / k, double(j) / k);
  for (int j = 0; j < k; ++j)
    for (int i = 0; i < k; ++i) {
      const int index = j * k + i;
      s.parts[index] = grid_cell(p.polygon, k, k, i, j);
      s.targets[index] = s.parts[index].centroid();
    }
  return s;
}

bool faces_shooter(const Vec3& point, const Vec3& normal, const Shooter& shooter) {
  if (glm::dot(shooter.normal, point - shooter.polygon[0]) <= 0.0) return false;
  for (int i = 0; i < shooter.polygon.count; ++i)
    if (glm::dot(normal, shooter.polygon[i] - point) > 0.0) return true;
  return false;
}

}  // namespace ncube

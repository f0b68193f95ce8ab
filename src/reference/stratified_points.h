// Points spread over an element for the reference's area integrals (docs/accuracy.md):
// K = s x s jittered strata of the element's bilinear parameter square, each point weighted
// by the map's Jacobian, so that sum_k weight_k f(point_k) / K estimates the integral of f
// over the element for any quad or triangle (the triangle's map collapsed at v2 is not
// area-uniform; the weights make it exact in expectation). Independent of the simulator's
// sampling (the shooter's parts, the element centres): only the polygon is shared.
#pragma once

#include <cstdint>
#include <vector>

#include "geometry/polygon.h"

namespace ncube::reference {

struct AreaSample {
  Vec3 point;
  double weight = 0.0;  // |dp/du x dp/dv| at the point: the mean over the strata is the area
};

// A deterministic stream of doubles in [0, 1) from a 64-bit seed (SplitMix64; the standard
// library's distributions are not the same on every platform).
class SampleStream {
 public:
  explicit SampleStream(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next_bits();
  double next_unit() { return double(next_bits() >> 11) * 0x1.0p-53; }

 private:
  std::uint64_t state_;
};

// One 64-bit seed from several numbers (the run's seed, an element, a pair).
std::uint64_t mix_seed(std::uint64_t a, std::uint64_t b, std::uint64_t c = 0);

// `side` x `side` jittered points on the polygon, stratum (a, b) at index b * side + a.
std::vector<AreaSample> stratified_points(const Polygon& polygon, int side, std::uint64_t seed);

}  // namespace ncube::reference

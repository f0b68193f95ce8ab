// Visibility between two surface points for the reference solution: one Embree ray
// (Intel's ray-tracing kernels, Debian libembree-dev) through every patch of the scene, in
// Embree's robust mode. Separate from the simulator's visibility (the exact double test of
// src/visibility, and src/host/embree_scene.h, which only proposes blockers to it): the
// reference must share no code with the methods it judges. Single precision is enough here:
// each end is lifted off its surface by kLift of the scene's diagonal along its normal
// (thousands of times Embree's rounding), which decides nothing the integrals can see.
#pragma once

#include <embree3/rtcore.h>

#include <vector>

#include "scene/scene.h"

namespace ncube::reference {

class RayVisibility {
 public:
  static constexpr double kLift = 1e-5;  // of the scene's bounding-box diagonal

  explicit RayVisibility(const Scene& scene);
  ~RayVisibility();
  RayVisibility(const RayVisibility&) = delete;
  RayVisibility& operator=(const RayVisibility&) = delete;

  // Whether the segment between `a` (on a surface with unit normal na) and `b` (normal nb)
  // meets no patch. Safe to call from several threads at once.
  bool visible(const Vec3& a, const Vec3& na, const Vec3& b, const Vec3& nb) const;

  // What the ray from `a` (on a surface with unit normal na, lifted as above) along
  // `direction` meets first: nothing (it leaves the scene), a patch's front (the side its
  // normal points to) or a patch's back.
  enum class Hit { kNothing, kFront, kBack };
  Hit first_hit(const Vec3& a, const Vec3& na, const Vec3& direction) const;

 private:
  std::vector<Vec3> triangle_normals_;  // each triangle's patch normal, by Embree's primID
  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
  double lift_ = 0.0;
};

}  // namespace ncube::reference

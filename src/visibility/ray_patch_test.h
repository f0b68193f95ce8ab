// The exact ray-patch test of the paper's brute-force loop (section 2.2), in doubles: the
// reference every faster way of answering "is this ray blocked" must agree with.
#pragma once

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "geometry/polygon.h"
#include "scene/scene.h"

namespace ncube {

// One patch with what the exact segment test needs.
struct PatchCandidate {
  Vec3 vertices[4];
  int vertex_count;
  Vec3 normal;
  double plane_offset;  // normal . x for points x of the plane
  int scene_index;
};

PatchCandidate make_candidate(const Polygon& polygon, const Vec3& normal, int scene_index);

// The candidate's axis-aligned bounding box, grown by `margin` on every side.
inline void grown_box(const PatchCandidate& c, double margin, Vec3& lo, Vec3& hi) {
  lo = Vec3(1e300);
  hi = Vec3(-1e300);
  for (int i = 0; i < c.vertex_count; ++i) {
    lo = glm::min(lo, c.vertices[i]);
    hi = glm::max(hi, c.vertices[i]);
  }
  lo -= Vec3(margin);
  hi += Vec3(margin);
}

// Distances from a plane within this count as "on the plane" in the loop's side tests (plane
// crossings): relative to the scene's size.
inline double plane_side_tolerance(const Scene& scene) {
  return 1e-9 * (1.0 + scene_bounds(scene).diagonal());
}

// Ends of a shadow ray lie on the receiver and on the shooter; a relative margin keeps the
// surfaces they start and end on (and coplanar neighbours) from blocking them.
constexpr double kRayEpsilon = 1e-9;

// The test's first half: does the segment from + t * delta, t in (kRayEpsilon,
// 1 - kRayEpsilon), meet the candidate's plane, and where (x)? It reads only the plane, so it
// is the same for all patches with the same normal and offset.
inline bool segment_meets_plane(const PatchCandidate& c, const Vec3& from, const Vec3& delta,
                                Vec3& x) {
  const double denominator = glm::dot(c.normal, delta);
  if (denominator == 0.0) return false;  // parallel to the plane
  const double t = (c.plane_offset - glm::dot(c.normal, from)) / denominator;
  if (!(t > kRayEpsilon && t < 1.0 - kRayEpsilon)) return false;
  x = from + t * delta;
  return true;
}

// The second half: is x, where the segment meets the plane, inside the polygon (edges
// included)?
inline bool plane_point_inside(const PatchCandidate& c, const Vec3& x) {
  for (int k = 0; k < c.vertex_count; ++k) {
    const Vec3& a = c.vertices[k];
    const Vec3& b = c.vertices[(k + 1) % c.vertex_count];
    if (glm::dot(c.normal, glm::cross(b - a, x - a)) < 0.0) return false;
  }
  return true;
}

// Does the segment from + t * delta, t in (kRayEpsilon, 1 - kRayEpsilon), cross the
// candidate's polygon (edges included)? Inline: Embree's filter calls it for every hit.
inline bool segment_crosses(const PatchCandidate& c, const Vec3& from, const Vec3& delta) {
  Vec3 x;
  return segment_meets_plane(c, from, delta, x) && plane_point_inside(c, x);
}

}  // namespace ncube

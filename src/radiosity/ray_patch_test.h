// The exact ray-patch test of the paper's brute-force loop (section 2.2), in doubles: the
// reference every faster way of answering "is this ray blocked" must agree with.
#pragma once

#include "geometry/polygon.h"

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

// Ends of a shadow ray lie on the receiver and on the shooter; a relative margin keeps the
// surfaces they start and end on (and coplanar neighbours) from blocking them.
constexpr double kRayEpsilon = 1e-9;

// Does the segment from + t * delta, t in (kRayEpsilon, 1 - kRayEpsilon), cross the
// candidate's polygon (edges included)?
bool segment_crosses(const PatchCandidate& c, const Vec3& from, const Vec3& delta);

}  // namespace ncube

// The exact ray-patch test (visibility/ray_patch_test.h) in fewer operations for the patches
// most scenes are made of: rectangles in a plane x, y or z = constant with edges along the
// other two axes. Embree's occlusion filter runs the exact test on every hit it reports
// (embree_scene.h), so this is where the host spends its time per proposed hit.
//
// Why it is the same test, bit for bit. For such a patch the normal is n e_a (the other
// components exactly 0; n is +-1 up to the rounding of the normalisation, |n| > 1/2), every
// edge b - a has one non-zero component u along an in-plane axis e, and the exact test's sum
// dot(normal, cross(b - a, x - a)) has one non-zero term, n * (+-(u * (x_o - a_o))), where o
// is the third axis: every other product has a zero factor and adds a signed zero, which
// changes neither a non-zero sum nor the comparison "< 0" of a zero one. Its sign is that of
// g * (x_o - a_o) with g = +-u (sign flips are exact, rounding is symmetric, and n * v cannot
// round to zero when |n| > 1/2), so that is the comparison made here. Likewise dot(normal,
// delta) is n delta_a and dot(normal, from) is n from_a, the same rounded products. That
// needs every product finite: the test is used only when every coordinate of the scene is
// at most kMaxCoordinate in size (points on the segment between two points of the scene are
// then too, and no product reaches the double range).
// Other patches (triangles, slanted quads, larger coordinates) take the exact test itself.
// Contract (host side): it changes no answer and no count (tests/axis_patch_test.cpp tries
// it against segment_crosses on rays aimed at edges, corners and their neighbouring
// doubles).
#pragma once

#include <cstdint>
#include <vector>

#include "host/host_side.h"
#include "visibility/ray_patch_test.h"

namespace ncube {

class AxisPatchTest {
 public:
  static constexpr double kMaxCoordinate = 1e150;

  // One record per candidate; the fast form where it applies (and the scene's coordinates
  // all stay within kMaxCoordinate), otherwise a pointer back to the exact test.
  explicit AxisPatchTest(const std::vector<PatchCandidate>& candidates);

  // segment_crosses(candidates[position], from, delta), the same answer.
  __attribute__((always_inline)) bool crosses(int position, const Vec3& from,
                                              const Vec3& delta) const {
    const Record& r = records_[std::size_t(position)];
    if (r.axis < 0) return segment_crosses(candidates_[std::size_t(position)], from, delta);
    const double denominator = r.normal * delta[r.axis];
    if (denominator == 0.0) return false;
    const double t = (r.offset - r.normal * from[r.axis]) / denominator;
    if (!(t > kRayEpsilon && t < 1.0 - kRayEpsilon)) return false;
    for (int k = 0; k < r.edges; ++k) {
      const int o = r.other[k];
      if (r.signed_length[k] * ((from[o] + t * delta[o]) - r.corner[k]) < 0.0) return false;
    }
    return true;
  }

  // The loops' plane side test, sign of dot(normal, x) - offset beyond +-tolerance, the same
  // answer (the same rounded product n * x_a, the zero terms aside).
  __attribute__((always_inline)) int side(int position, const Vec3& x, double tolerance) const {
    const Record& r = records_[std::size_t(position)];
    const PatchCandidate& c = candidates_[std::size_t(position)];
    const double distance =
        r.axis >= 0 ? r.normal * x[r.axis] - r.offset : glm::dot(c.normal, x) - c.plane_offset;
    return distance > tolerance ? 1 : (distance < -tolerance ? -1 : 0);
  }

  // Whether the candidate at `position` takes the fast form (for tests and reports).
  bool fast(int position) const { return records_[std::size_t(position)].axis >= 0; }

  // The fast form's terms (octree_lanes.h runs the same test for eight rays at a time).
  struct Record {
    std::int8_t axis = -1;   // a: the normal's axis, -1 for the exact test itself
    std::int8_t edges = 0;
    std::int8_t other[4] = {0, 0, 0, 0};  // o of each edge
    double normal = 0.0;     // n, the normal's component along a
    double offset = 0.0;     // the plane offset, as the exact test has it
    double signed_length[4] = {0, 0, 0, 0};  // g of each edge
    double corner[4] = {0, 0, 0, 0};         // a_o of each edge
  };
  const Record& record(int position) const { return records_[std::size_t(position)]; }

 private:
  const std::vector<PatchCandidate>& candidates_;
  std::vector<Record> records_;
};

}  // namespace ncube

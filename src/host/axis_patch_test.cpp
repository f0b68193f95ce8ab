#include "host/axis_patch_test.h"

#include <cmath>
#include <glm/geometric.hpp>

namespace ncube {
namespace {

// The axis a when n is +-e_a (the other components exactly 0), else -1.
int normal_axis(const Vec3& n) {
  for (int a = 0; a < 3; ++a)
    if (std::fabs(n[a]) > 0.5 && n[(a + 1) % 3] == 0.0 && n[(a + 2) % 3] == 0.0) return a;
  return -1;
}

}  // namespace

AxisPatchTest::AxisPatchTest(const std::vector<PatchCandidate>& candidates)
    : candidates_(candidates), records_(candidates.size()) {
  for (const PatchCandidate& c : candidates)
    for (int k = 0; k < c.vertex_count; ++k)
      for (int axis = 0; axis < 3; ++axis)
        if (!(std::fabs(c.vertices[k][axis]) <= kMaxCoordinate)) return;  // all exact tests
  for (std::size_t position = 0; position < candidates.size(); ++position) {
    const PatchCandidate& c = candidates[position];
    const int a = normal_axis(c.normal);
    if (a < 0) continue;
    Record r;
    r.axis = std::int8_t(a);
    r.normal = c.normal[a];
    r.offset = c.plane_offset;
    r.edges = std::int8_t(c.vertex_count);
    bool fits = true;
    for (int k = 0; k < c.vertex_count && fits; ++k) {
      const Vec3& from = c.vertices[k];
      const Vec3& to = c.vertices[(k + 1) % c.vertex_count];
      if (from[a] != c.vertices[0][a]) fits = false;  // every corner in the plane a = const
      // The edge runs along one in-plane axis e (and not along a).
      int along = -1, moving = 0;
      for (int axis = 0; axis < 3; ++axis)
        if (to[axis] - from[axis] != 0.0) {
          along = axis;
          ++moving;
        }
      if (moving != 1 || along == a) {
        fits = false;
        break;
      }
      const int o = 3 - a - along;
      Vec3 unit_o(0.0);
      unit_o[o] = 1.0;
      r.other[k] = std::int8_t(o);
      // g = +-(b_e - a_e), with the sign of the exact test's factor of (x_o - a_o), worked
      // out by the test's own formula.
      r.signed_length[k] = std::copysign(std::fabs(to[along] - from[along]),
                                         glm::dot(c.normal, glm::cross(to - from, unit_o)));
      r.corner[k] = from[o];
    }
    if (fits) records_[position] = r;
  }
}

}  // namespace ncube

// The patches near a point: those whose bounding box, grown by a radius, contains it. Every
// point of a patch within that radius (in any direction) of the point is then among them
// (the box test is a per-axis test, weaker than the distance). EmbreeScene tests them
// exactly for the ends of its rays, the parts of a ray Embree is not asked about
// (embree_scene.h, docs/performance.md). A uniform grid over the grown boxes finds them:
// each cell lists the patches whose grown box overlaps it; a point reads its cell's list and
// keeps those whose grown box holds it, so the answer is the box test's alone, whatever the
// grid's resolution.
// Contract (host side): it changes no answer and no count; its answer is the box test's
// alone (tests/near_patches_test.cpp).
#pragma once

#include "host/host_side.h"

#include <array>
#include <cmath>
#include <vector>

#include "visibility/ray_patch_test.h"

namespace ncube {

class NearPatches {
 public:
  NearPatches(const std::vector<PatchCandidate>& candidates, double radius);

  // Calls visit(position) for every candidate whose bounding box grown by the radius holds x
  // (edges included), in position order.
  template <class Visit>
  void for_each_near(const Vec3& x, Visit&& visit) const {
    if (!(x.x >= lo_.x && x.x <= hi_.x && x.y >= lo_.y && x.y <= hi_.y && x.z >= lo_.z &&
          x.z <= hi_.z))
      return;  // outside every grown box (and not a number: nothing is near)
    const int cell = (cell_index(2, x.z) * cells_[1] + cell_index(1, x.y)) * cells_[0] +
                     cell_index(0, x.x);
    for (int i = first_[std::size_t(cell)]; i < first_[std::size_t(cell) + 1]; ++i) {
      const int position = members_[std::size_t(i)];
      const Vec3& lo = box_lo_[std::size_t(position)];
      const Vec3& hi = box_hi_[std::size_t(position)];
      if (x.x >= lo.x && x.x <= hi.x && x.y >= lo.y && x.y <= hi.y && x.z >= lo.z && x.z <= hi.z)
        visit(position);
    }
  }

 private:
  // The cell along `axis` of coordinate v: non-decreasing in v (a subtraction, a product by
  // a positive number, a floor and a clamp, each monotone in floating point), so a box's
  // cells from its low to its high corner include the cell of every point inside it.
  int cell_index(int axis, double v) const {
    const double f = std::floor((v - lo_[axis]) * per_unit_[std::size_t(axis)]);
    return f <= 0.0 ? 0 : (f >= double(cells_[axis] - 1) ? cells_[axis] - 1 : int(f));
  }

  std::vector<Vec3> box_lo_, box_hi_;  // per position: the grown bounding box
  Vec3 lo_{0.0}, hi_{-1.0};            // the union of the grown boxes
  std::array<int, 3> cells_{1, 1, 1};
  std::array<double, 3> per_unit_{0.0, 0.0, 0.0};  // cells per scene unit, per axis
  std::vector<int> first_, members_;  // cell c lists members_[first_[c] .. first_[c + 1])
};

}  // namespace ncube

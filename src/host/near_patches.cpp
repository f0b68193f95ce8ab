#include "host/near_patches.h"

#include <algorithm>

namespace ncube {

NearPatches::NearPatches(const std::vector<PatchCandidate>& candidates, double radius) {
  const std::size_t n = candidates.size();
  box_lo_.reserve(n);
  box_hi_.reserve(n);
  lo_ = Vec3(1e300);
  hi_ = Vec3(-1e300);
  for (const PatchCandidate& c : candidates) {
    Vec3 lo, hi;
    grown_box(c, radius, lo, hi);
    box_lo_.push_back(lo);
    box_hi_.push_back(hi);
    lo_ = glm::min(lo_, box_lo_.back());
    hi_ = glm::max(hi_, box_hi_.back());
  }
  if (n == 0) {
    lo_ = Vec3(0.0);
    hi_ = Vec3(-1.0);  // holds no point
    first_.assign(2, 0);
    return;
  }
  // Choice: about 4 cells per patch, cubic where the extents allow (a room's patches lie on
  // its surfaces, so most cells are empty and a surface cell lists a few patches).
  const Vec3 extent = hi_ - lo_;
  const double volume = extent.x * extent.y * extent.z;
  // A flat scene (one extent near 2 radius) would get too many: the edge then grows until
  // there are at most 8 per patch.
  double edge = std::cbrt(volume / (4.0 * double(n)));
  for (;; edge *= 1.25) {
    double cell_count = 1.0;
    for (int axis = 0; axis < 3; ++axis) {
      cells_[std::size_t(axis)] = std::clamp(int(extent[axis] / edge), 1, 256);
      cell_count *= double(cells_[std::size_t(axis)]);
    }
    if (cell_count <= 8.0 * double(n) + 64.0) break;
  }
  for (int axis = 0; axis < 3; ++axis)
    per_unit_[std::size_t(axis)] = double(cells_[std::size_t(axis)]) / extent[axis];
  const std::size_t cell_count = std::size_t(cells_[0]) * std::size_t(cells_[1]) * std::size_t(cells_[2]);
  first_.assign(cell_count + 1, 0);
  // Two passes over the cells of each grown box: count, then fill (positions ascending).
  auto for_each_cell = [&](std::size_t position, auto&& f) {
    const Vec3& lo = box_lo_[position];
    const Vec3& hi = box_hi_[position];
    for (int z = cell_index(2, lo.z); z <= cell_index(2, hi.z); ++z)
      for (int y = cell_index(1, lo.y); y <= cell_index(1, hi.y); ++y)
        for (int x = cell_index(0, lo.x); x <= cell_index(0, hi.x); ++x)
          f(std::size_t((z * cells_[1] + y) * cells_[0] + x));
  };
  for (std::size_t p = 0; p < n; ++p) for_each_cell(p, [&](std::size_t cell) { ++first_[cell + 1]; });
  for (std::size_t c = 0; c < cell_count; ++c) first_[c + 1] += first_[c];
  members_.resize(std::size_t(first_.back()));
  std::vector<int> next(first_.begin(), first_.end() - 1);
  for (std::size_t p = 0; p < n; ++p)
    for_each_cell(p, [&](std::size_t cell) { members_[std::size_t(next[cell]++)] = int(p); });
}

}  // namespace ncube

#include "visibility/octree.h"

#include <algorithm>
#include <stdexcept>


namespace ncube {

Octree::Octree(const Scene& scene, const std::vector<int>& patch_indices, OctreeParameters parameters)
    : parameters_(parameters), patch_indices_(patch_indices) {
  if (parameters_.max_depth < 0 || parameters_.max_depth > 60 || parameters_.max_leaf_patches < 1)
    throw std::invalid_argument("Octree: max_depth must be 0..60 and max_leaf_patches at least 1");
  const double scale = 1.0 + scene_bounds(scene).diagonal();
  side_tolerance_ = plane_side_tolerance(scene);  // the brute-force loop's
  // A hit point is computed with rounding errors of about 1e-16 x scale; boxes grown by far
  // more than that keep every hit inside a visited leaf that lists the patch.
  pad_ = 1e-9 * scale;
  Vec3 root_lo(1e300), root_hi(-1e300);
  for (int scene_index : patch_indices) {
    const Patch& p = scene.patches[std::size_t(scene_index)];
    const PatchCandidate c = make_candidate(p.polygon, p.normal, scene_index);
    Vec3 lo, hi;
    grown_box(c, pad_, lo, hi);
    patches_.push_back(c);
    box_lo_.push_back(lo);
    box_hi_.push_back(hi);
    root_lo = glm::min(root_lo, box_lo_.back());
    root_hi = glm::max(root_hi, box_hi_.back());
  }
  if (patches_.empty()) return;
  cells_.push_back(Cell{root_lo, root_hi});
  build_.cells = 1;
  std::vector<std::int32_t> all(patches_.size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = std::int32_t(i);
  split(0, std::move(all), 0);
  walk_bounds_.reserve(6 * cells_.size());
  for (const Cell& c : cells_)
    for (const double x : {c.lo.x - pad_, c.lo.y - pad_, c.lo.z - pad_, c.hi.x + pad_,
                           c.hi.y + pad_, c.hi.z + pad_})
      walk_bounds_.push_back(x);
}

void Octree::split(int cell, std::vector<std::int32_t> patches, int depth) {
  if (int(patches.size()) <= parameters_.max_leaf_patches || depth >= parameters_.max_depth) {
    cells_[std::size_t(cell)].patch_begin = std::int32_t(references_.size());
    cells_[std::size_t(cell)].patch_count = std::int32_t(patches.size());
    references_.insert(references_.end(), patches.begin(), patches.end());
    build_.patch_references += patches.size();
    ++build_.leaves;
    return;
  }
  const Vec3 lo = cells_[std::size_t(cell)].lo, hi = cells_[std::size_t(cell)].hi;
  const Vec3 mid = 0.5 * (lo + hi);
  const int first = int(cells_.size());
  cells_[std::size_t(cell)].first_child = first;
  for (int child = 0; child < 8; ++child) {
    Cell c;
    c.lo = Vec3(child & 1 ? mid.x : lo.x, child & 2 ? mid.y : lo.y, child & 4 ? mid.z : lo.z);
    c.hi = Vec3(child & 1 ? hi.x : mid.x, child & 2 ? hi.y : mid.y, child & 4 ? hi.z : mid.z);
    cells_.push_back(c);
  }
  build_.cells += 8;
  // A patch goes into every child its (grown) bounding box overlaps, edges included.
  std::vector<std::int32_t> lists[8];
  for (std::int32_t position : patches)
    for (int child = 0; child < 8; ++child) {
      ++build_.overlap_tests;
      const Cell& c = cells_[std::size_t(first + child)];
      const Vec3& a = box_lo_[std::size_t(position)];
      const Vec3& b = box_hi_[std::size_t(position)];
      if (a.x <= c.hi.x && b.x >= c.lo.x && a.y <= c.hi.y && b.y >= c.lo.y && a.z <= c.hi.z &&
          b.z >= c.lo.z)
        lists[child].push_back(position);
    }
  for (int child = 0; child < 8; ++child) split(first + child, std::move(lists[child]), depth + 1);
}

bool Octree::segment_meets_cell(int cell, const Vec3& from, const Vec3& delta) const {
  // Slab test of the segment from + t delta, t in [0, 1], against the cell grown by pad_.
  const double* bounds = walk_bounds_.data() + 6 * std::size_t(cell);
  double t_enter = 0.0, t_exit = 1.0;
  for (int axis = 0; axis < 3; ++axis) {
    const double lo = bounds[axis], hi = bounds[3 + axis];
    if (delta[axis] == 0.0) {
      if (from[axis] < lo || from[axis] > hi) return false;
      continue;
    }
    double t0 = (lo - from[axis]) / delta[axis], t1 = (hi - from[axis]) / delta[axis];
    if (t0 > t1) std::swap(t0, t1);
    t_enter = std::max(t_enter, t0);
    t_exit = std::min(t_exit, t1);
    if (t_enter > t_exit) return false;
  }
  return true;
}

bool Octree::ray_blocked(const Vec3& from, const Vec3& target, int receiver_patch,
                         int shooter_patch, WorkCounts& counts, Scratch& scratch) const {
  if (cells_.empty()) return false;
  const Vec3 delta = target - from;
  // Children in the order the segment can meet them: along an axis where it runs downwards
  // it meets the upper half first, so the child index is flipped in that bit (a segment's
  // cells have each index bit changing at most once, the same way).
  const int flip = (delta.x < 0.0 ? 1 : 0) | (delta.y < 0.0 ? 2 : 0) | (delta.z < 0.0 ? 4 : 0);
  if (++scratch.ray == 0) {  // the stamps wrapped around: start the mailbox afresh
    std::fill(scratch.tested_for_ray.begin(), scratch.tested_for_ray.end(), 0);
    scratch.ray = 1;
  }
  std::int32_t stack[8 * 64 + 1];  // depth-first: at most 7 siblings waiting per level
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const int index = stack[--top];
    ++counts.octree_cells_visited;
    if (!segment_meets_cell(index, from, delta)) continue;
    const Cell& cell = cells_[std::size_t(index)];
    if (cell.first_child >= 0) {
      for (int k = 7; k >= 0; --k) stack[top++] = cell.first_child + (k ^ flip);  // first on top
      continue;
    }
    for (std::int32_t i = cell.patch_begin; i < cell.patch_begin + cell.patch_count; ++i) {
      const std::int32_t position = references_[std::size_t(i)];
      if (scratch.tested_for_ray[std::size_t(position)] == scratch.ray) continue;  // mailbox
      scratch.tested_for_ray[std::size_t(position)] = scratch.ray;
      const PatchCandidate& c = patches_[std::size_t(position)];
      if (c.scene_index == receiver_patch || c.scene_index == shooter_patch) continue;
      ++counts.ray_patch_tests;
      if (side_of(c, from) * side_of(c, target) < 0) ++counts.plane_crossings;
      if (segment_crosses(c, from, delta)) return true;  // the first blocker ends the walk
    }
  }
  return false;
}

PartMask Octree::unblocked_parts(const Vec3& point, int receiver_patch, const Shooter& shooter,
                                 WorkCounts& counts, Scratch& scratch) const {
  PartMask visible = 0;
  for (int part = 0; part < shooter.part_count; ++part) {
    ++counts.rays;
    if (!ray_blocked(point, shooter.targets[part], receiver_patch, shooter.patch, counts, scratch))
      visible |= PartMask(1) << part;
  }
  return visible;
}

void Octree::unblocked_parts(const PointBlock& block, const Shooter& shooter, PartMask* masks,
                             WorkCounts& counts) const {
  Scratch scratch = make_scratch();
  for (std::size_t k = 0; k < block.count; ++k)
    masks[k] = unblocked_parts(block.points[k], block.patches[k], shooter, counts, scratch);
}

WorkCounts Octree::build_work() const {
  WorkCounts work;
  work.octree_overlap_tests = build_.overlap_tests;
  work.octree_cells_built = build_.cells;
  return work;
}

HeldItems Octree::structure_items() const {
  HeldItems items;
  items.octree_cells = double(build_.cells);
  items.octree_references = double(build_.patch_references);
  return items;
}

}  // namespace ncube

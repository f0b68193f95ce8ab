#include "host/fast_octree.h"

#include <algorithm>

namespace ncube {

unsigned FastOctree::children_met(const Octree::Cell& cell, const Vec3& from,
                                  const Vec3& delta) const {
  // Child 0 has the lower half on every axis, child 7 the upper: their stored (grown) bounds
  // are the halves' bounds of every child.
  const double* lower = octree_->walk_bounds().data() + 6 * std::size_t(cell.first_child);
  const double* upper = lower + 6 * 7;
  bool inside[3][2];
  double enter[3][2], exit[3][2];
  for (int axis = 0; axis < 3; ++axis)
    for (int half = 0; half < 2; ++half) {
      const double* bounds = half ? upper : lower;
      const double lo = bounds[axis], hi = bounds[3 + axis];
      if (delta[axis] == 0.0) {  // as Octree::segment_meets_cell: no interval, only inside
        inside[axis][half] = !(from[axis] < lo || from[axis] > hi);
        enter[axis][half] = 0.0;  // neutral: the walk's interval starts at [0, 1]
        exit[axis][half] = 1.0;
        continue;
      }
      double t0 = (lo - from[axis]) / delta[axis], t1 = (hi - from[axis]) / delta[axis];
      if (t0 > t1) std::swap(t0, t1);
      inside[axis][half] = true;
      enter[axis][half] = t0;
      exit[axis][half] = t1;
    }
  unsigned met = 0;
  for (int child = 0; child < 8; ++child) {
    const int x = child & 1, y = (child >> 1) & 1, z = (child >> 2) & 1;
    if (!inside[0][x] || !inside[1][y] || !inside[2][z]) continue;
    const double t_enter = std::max({0.0, enter[0][x], enter[1][y], enter[2][z]});
    const double t_exit = std::min({1.0, exit[0][x], exit[1][y], exit[2][z]});
    if (t_enter <= t_exit) met |= 1u << child;
  }
  return met;
}

bool FastOctree::ray_blocked(const Vec3& from, const Vec3& target, int receiver_patch,
                             int shooter_patch, WorkCounts& counts,
                             Octree::Scratch& scratch) const {
  const std::vector<Octree::Cell>& cells = octree_->cells();
  if (cells.empty()) return false;
  const Vec3 delta = target - from;
  // The walk's order (Octree::ray_blocked): along an axis where the segment runs downwards
  // the upper half comes first.
  const int flip = (delta.x < 0.0 ? 1 : 0) | (delta.y < 0.0 ? 2 : 0) | (delta.z < 0.0 ? 4 : 0);
  if (++scratch.ray == 0) {
    std::fill(scratch.tested_for_ray.begin(), scratch.tested_for_ray.end(), 0);
    scratch.ray = 1;
  }
  const std::vector<std::int32_t>& references = octree_->references();
  const std::vector<PatchCandidate>& patches = octree_->patches();
  // Depth-first as the walk; a missed cell is pushed as ~index: it is still counted when
  // popped, as the walk counts the slab test that misses it.
  std::int32_t stack[8 * 64 + 1];
  int top = 0;
  ++counts.octree_cells_visited;
  if (!octree_->segment_meets_cell(0, from, delta)) return false;
  stack[top++] = 0;
  bool root = true;
  while (top > 0) {
    const std::int32_t entry = stack[--top];
    if (!root) ++counts.octree_cells_visited;
    root = false;
    if (entry < 0) continue;  // missed
    const Octree::Cell& cell = cells[std::size_t(entry)];
    if (cell.first_child >= 0) {
      const unsigned met = children_met(cell, from, delta);
      for (int k = 7; k >= 0; --k) {
        const int child = k ^ flip;
        const std::int32_t index = cell.first_child + child;
        stack[top++] = (met >> child) & 1u ? index : ~index;  // first on top
      }
      continue;
    }
    for (std::int32_t i = cell.patch_begin; i < cell.patch_begin + cell.patch_count; ++i) {
      const std::int32_t position = references[std::size_t(i)];
      if (scratch.tested_for_ray[std::size_t(position)] == scratch.ray) continue;  // mailbox
      scratch.tested_for_ray[std::size_t(position)] = scratch.ray;
      const PatchCandidate& c = patches[std::size_t(position)];
      if (c.scene_index == receiver_patch || c.scene_index == shooter_patch) continue;
      ++counts.ray_patch_tests;
      if (octree_->side_of(c, from) * octree_->side_of(c, target) < 0) ++counts.plane_crossings;
      if (segment_crosses(c, from, delta)) return true;  // the first blocker ends the walk
    }
  }
  return false;
}

void FastOctree::unblocked_parts(const PointBlock& block, const Shooter& shooter,
                                 PartMask* masks, WorkCounts& counts) const {
  Octree::Scratch scratch = octree_->make_scratch();
  for (std::size_t k = 0; k < block.count; ++k) {
    PartMask visible = 0;
    for (int part = 0; part < shooter.part_count; ++part) {
      ++counts.rays;
      if (!ray_blocked(block.points[k], shooter.targets[part], block.patches[k], shooter.patch,
                       counts, scratch))
        visible |= PartMask(1) << part;
    }
    masks[k] = visible;
  }
}

}  // namespace ncube

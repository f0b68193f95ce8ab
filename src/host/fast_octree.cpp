#include "host/fast_octree.h"

#include <algorithm>
#include <cmath>
#ifdef __SSE2__
#include <emmintrin.h>
#endif

namespace ncube {

struct FastOctree::Packet {
  Vec3 from;
  int receiver_patch = -1, shooter_patch = -1;
  int flip = 0;  // the walk's child order: bit a set where the rays run downwards on axis a
  int size = 0;
  int part[kMaxShooterParts];
  Vec3 target[kMaxShooterParts];
  double delta[3][kMaxShooterParts];  // per axis, per ray
};

struct FastOctree::Mailbox {
  explicit Mailbox(std::size_t patches) : packet(patches, 0), tested(patches, 0) {}
  // The rays of packet `current` that have tested patch `position`.
  std::uint64_t& rays(std::size_t position) {
    if (packet[position] != current) {
      packet[position] = current;
      tested[position] = 0;
    }
    return tested[position];
  }
  void next_packet() {
    if (++current == 0) {  // the stamps wrapped around: start afresh
      std::fill(packet.begin(), packet.end(), 0);
      current = 1;
    }
  }
  std::vector<std::uint32_t> packet;
  std::vector<std::uint64_t> tested;
  std::uint32_t current = 0;
};

namespace {

int direction_signs(const Vec3& delta) {
  return (delta.x < 0.0 ? 1 : 0) | (delta.y < 0.0 ? 2 : 0) | (delta.z < 0.0 ? 4 : 0);
}

}  // namespace

void FastOctree::children_met(const Octree::Cell& cell, const Packet& packet, std::uint64_t rays,
                              std::uint64_t met[8]) const {
  // Child 0 has the lower half on every axis, child 7 the upper: their stored (grown) bounds
  // are the halves' bounds of every child.
  const double* lower = octree_->walk_bounds().data() + 6 * std::size_t(cell.first_child);
  const double* upper = lower + 6 * 7;
  double to_lo[3][2], to_hi[3][2];  // the slab test's numerators, the same for every ray
  bool holds_from[3][2];            // the point lies within the half's slab
  for (int axis = 0; axis < 3; ++axis)
    for (int half = 0; half < 2; ++half) {
      const double* bounds = half ? upper : lower;
      const double lo = bounds[axis], hi = bounds[3 + axis];
      to_lo[axis][half] = lo - packet.from[axis];
      to_hi[axis][half] = hi - packet.from[axis];
      holds_from[axis][half] = !(packet.from[axis] < lo || packet.from[axis] > hi);
    }
  std::fill(met, met + 8, std::uint64_t(0));
#ifdef __SSE2__
  // Two rays at a time. Where a ray runs parallel to an axis, the half's interval is [0, 1]
  // if the point lies in its slab and empty ([+inf, -inf]) if not, as the walk's test (which
  // then has no interval, only inside); elsewhere t0 and t1 are the walk's quotients, ordered
  // as the walk orders them. No quotient is NaN where it is used, so max and min give the
  // walk's values.
  const __m128d zero = _mm_setzero_pd(), one = _mm_set1_pd(1.0);
  const __m128d infinity = _mm_set1_pd(HUGE_VAL), minus_infinity = _mm_set1_pd(-HUGE_VAL);
  __m128d empty_enter[3][2], empty_exit[3][2];
  for (int axis = 0; axis < 3; ++axis)
    for (int half = 0; half < 2; ++half) {
      empty_enter[axis][half] = holds_from[axis][half] ? zero : infinity;
      empty_exit[axis][half] = holds_from[axis][half] ? one : minus_infinity;
    }
  for (std::uint64_t left = rays; left != 0;) {
    const int first = __builtin_ctzll(left);
    left &= left - 1;
    const int second = left != 0 ? __builtin_ctzll(left) : first;  // an odd ray out pairs itself
    if (left != 0) left &= left - 1;
    __m128d enter[3][2], exit[3][2];
    for (int axis = 0; axis < 3; ++axis) {
      const __m128d d = _mm_set_pd(packet.delta[axis][second], packet.delta[axis][first]);
      const __m128d parallel = _mm_cmpeq_pd(d, zero);
      for (int half = 0; half < 2; ++half) {
        const __m128d t0 = _mm_div_pd(_mm_set1_pd(to_lo[axis][half]), d);
        const __m128d t1 = _mm_div_pd(_mm_set1_pd(to_hi[axis][half]), d);
        const __m128d swapped = _mm_cmpgt_pd(t0, t1);
        const __m128d low = _mm_or_pd(_mm_and_pd(swapped, t1), _mm_andnot_pd(swapped, t0));
        const __m128d high = _mm_or_pd(_mm_and_pd(swapped, t0), _mm_andnot_pd(swapped, t1));
        enter[axis][half] = _mm_or_pd(_mm_and_pd(parallel, empty_enter[axis][half]),
                                      _mm_andnot_pd(parallel, low));
        exit[axis][half] = _mm_or_pd(_mm_and_pd(parallel, empty_exit[axis][half]),
                                     _mm_andnot_pd(parallel, high));
      }
    }
    const std::uint64_t first_bit = std::uint64_t(1) << first, second_bit = std::uint64_t(1) << second;
    for (int child = 0; child < 8; ++child) {
      const int x = child & 1, y = (child >> 1) & 1, z = (child >> 2) & 1;
      const __m128d t_enter =
          _mm_max_pd(_mm_max_pd(_mm_max_pd(zero, enter[0][x]), enter[1][y]), enter[2][z]);
      const __m128d t_exit =
          _mm_min_pd(_mm_min_pd(_mm_min_pd(one, exit[0][x]), exit[1][y]), exit[2][z]);
      const int meets = _mm_movemask_pd(_mm_cmple_pd(t_enter, t_exit));
      met[child] |= (meets & 1 ? first_bit : 0) | (meets & 2 ? second_bit : 0);
    }
  }
#else
  for (std::uint64_t left = rays; left != 0; left &= left - 1) {
    const int ray = __builtin_ctzll(left);
    bool inside[3][2];
    double enter[3][2], exit[3][2];
    for (int axis = 0; axis < 3; ++axis) {
      const double d = packet.delta[axis][ray];
      for (int half = 0; half < 2; ++half) {
        if (d == 0.0) {  // as Octree::segment_meets_cell: no interval, only inside
          inside[axis][half] = holds_from[axis][half];
          enter[axis][half] = 0.0;  // neutral: the walk's interval starts at [0, 1]
          exit[axis][half] = 1.0;
          continue;
        }
        double t0 = to_lo[axis][half] / d, t1 = to_hi[axis][half] / d;
        if (t0 > t1) std::swap(t0, t1);
        inside[axis][half] = true;
        enter[axis][half] = t0;
        exit[axis][half] = t1;
      }
    }
    const std::uint64_t bit = std::uint64_t(1) << ray;
    for (int child = 0; child < 8; ++child) {
      const int x = child & 1, y = (child >> 1) & 1, z = (child >> 2) & 1;
      if (!inside[0][x] || !inside[1][y] || !inside[2][z]) continue;
      const double t_enter = std::max({0.0, enter[0][x], enter[1][y], enter[2][z]});
      const double t_exit = std::min({1.0, exit[0][x], exit[1][y], exit[2][z]});
      if (t_enter <= t_exit) met[child] |= bit;
    }
  }
#endif
}

std::uint64_t FastOctree::meets_root_cell(const Packet& packet) const {
  std::uint64_t meets = 0;
#ifdef __SSE2__
  // Octree::segment_meets_cell(0, ...) for two rays at a time: the walk narrows [0, 1] axis
  // by axis and stops once it is empty, which it is at the end if and only if it is empty
  // at some axis (the bounds only narrow); a ray parallel to an axis meets the cell if the
  // point lies in its slab.
  const double* bounds = octree_->walk_bounds().data();
  const __m128d zero = _mm_setzero_pd(), one = _mm_set1_pd(1.0);
  for (int first = 0; first < packet.size; first += 2) {
    const int second = first + 1 < packet.size ? first + 1 : first;
    __m128d t_enter = zero, t_exit = one;
    int outside = 0;
    for (int axis = 0; axis < 3; ++axis) {
      const double lo = bounds[axis], hi = bounds[3 + axis], from = packet.from[axis];
      const __m128d d = _mm_set_pd(packet.delta[axis][second], packet.delta[axis][first]);
      const __m128d parallel = _mm_cmpeq_pd(d, zero);
      if (from < lo || from > hi) outside |= _mm_movemask_pd(parallel);
      __m128d t0 = _mm_div_pd(_mm_set1_pd(lo - from), d);
      __m128d t1 = _mm_div_pd(_mm_set1_pd(hi - from), d);
      const __m128d swapped = _mm_cmpgt_pd(t0, t1);
      const __m128d low = _mm_or_pd(_mm_and_pd(swapped, t1), _mm_andnot_pd(swapped, t0));
      const __m128d high = _mm_or_pd(_mm_and_pd(swapped, t0), _mm_andnot_pd(swapped, t1));
      // A parallel axis leaves the interval as it is.
      t_enter = _mm_or_pd(_mm_and_pd(parallel, t_enter), _mm_andnot_pd(parallel, _mm_max_pd(t_enter, low)));
      t_exit = _mm_or_pd(_mm_and_pd(parallel, t_exit), _mm_andnot_pd(parallel, _mm_min_pd(t_exit, high)));
    }
    const int met = _mm_movemask_pd(_mm_cmple_pd(t_enter, t_exit)) & ~outside;
    meets |= std::uint64_t(met & 1) << first;
    if (second != first) meets |= std::uint64_t(met >> 1 & 1) << second;
  }
#else
  for (int ray = 0; ray < packet.size; ++ray) {
    const Vec3 delta(packet.delta[0][ray], packet.delta[1][ray], packet.delta[2][ray]);
    if (octree_->segment_meets_cell(0, packet.from, delta)) meets |= std::uint64_t(1) << ray;
  }
#endif
  return meets;
}

std::uint64_t FastOctree::packet_blocked(const Packet& packet, WorkCounts& counts,
                                         Mailbox& mailbox) const {
  const std::vector<Octree::Cell>& cells = octree_->cells();
  if (cells.empty()) return 0;
  mailbox.next_packet();
  const std::vector<std::int32_t>& references = octree_->references();
  const std::vector<PatchCandidate>& patches = octree_->patches();
  // The root: visited by every ray, walked by those that meet it.
  counts.octree_cells_visited += std::uint64_t(packet.size);
  const std::uint64_t meets_root = meets_root_cell(packet);
  if (meets_root == 0) return 0;
  // Depth-first as the walk. An entry is counted as visited, when popped, by the rays that
  // pushed it (`pushed_by`) and are still walking, as each of them counts the slab test of
  // every child it pops, met or missed; it is walked by the rays among them that meet it.
  struct Entry {
    std::int32_t cell;
    std::uint64_t pushed_by, met_by;
  };
  Entry stack[8 * 64 + 1];
  int top = 0;
  stack[top++] = Entry{0, 0, meets_root};  // the root's visit is counted above
  std::uint64_t blocked = 0;
  while (top > 0) {
    const Entry entry = stack[--top];
    counts.octree_cells_visited += std::uint64_t(__builtin_popcountll(entry.pushed_by & ~blocked));
    std::uint64_t rays = entry.met_by & ~blocked;
    if (rays == 0) continue;
    const Octree::Cell& cell = cells[std::size_t(entry.cell)];
    if (cell.first_child >= 0) {
      std::uint64_t met[8];
      children_met(cell, packet, rays, met);
      for (int k = 7; k >= 0; --k) {
        const int child = k ^ packet.flip;
        stack[top++] = Entry{cell.first_child + child, rays, met[child]};  // first on top
      }
      continue;
    }
    for (std::int32_t i = cell.patch_begin; i < cell.patch_begin + cell.patch_count; ++i) {
      const std::int32_t position = references[std::size_t(i)];
      std::uint64_t& tested = mailbox.rays(std::size_t(position));
      const std::uint64_t asking = rays & ~tested;  // each ray tests a patch once
      if (asking == 0) continue;
      tested |= asking;
      const PatchCandidate& c = patches[std::size_t(position)];
      if (c.scene_index == packet.receiver_patch || c.scene_index == packet.shooter_patch) continue;
      const double tolerance = octree_->side_tolerance();
      const int side_of_from = exact_.side(position, packet.from, tolerance);
      for (std::uint64_t left = asking; left != 0; left &= left - 1) {
        const int ray = __builtin_ctzll(left);
        ++counts.ray_patch_tests;
        if (side_of_from * exact_.side(position, packet.target[ray], tolerance) < 0)
          ++counts.plane_crossings;
        const Vec3 delta(packet.delta[0][ray], packet.delta[1][ray], packet.delta[2][ray]);
        if (exact_.crosses(position, packet.from, delta)) {  // the first blocker ends its walk
          blocked |= std::uint64_t(1) << ray;
          rays &= ~(std::uint64_t(1) << ray);
        }
      }
      if (rays == 0) break;
    }
  }
  return blocked;
}

void FastOctree::unblocked_parts(const PointBlock& block, const Shooter& shooter,
                                 PartMask* masks, WorkCounts& counts) const {
  Mailbox mailbox(octree_->patches().size());
  Packet packet;
  packet.shooter_patch = shooter.patch;
  int signs[kMaxShooterParts];
  for (std::size_t k = 0; k < block.count; ++k) {
    packet.from = block.points[k];
    packet.receiver_patch = block.patches[k];
    counts.rays += std::uint64_t(shooter.part_count);
    PartMask waiting = 0;
    for (int part = 0; part < shooter.part_count; ++part) {
      signs[part] = direction_signs(shooter.targets[part] - packet.from);
      waiting |= PartMask(1) << part;
    }
    PartMask visible = 0;
    while (waiting != 0) {  // one packet per direction signs, in the order of their first part
      packet.flip = signs[__builtin_ctzll(waiting)];
      packet.size = 0;
      for (PartMask left = waiting; left != 0; left &= left - 1) {
        const int part = __builtin_ctzll(left);
        if (signs[part] != packet.flip) continue;
        const int ray = packet.size++;
        const Vec3 delta = shooter.targets[part] - packet.from;
        packet.part[ray] = part;
        packet.target[ray] = shooter.targets[part];
        for (int axis = 0; axis < 3; ++axis) packet.delta[axis][ray] = delta[axis];
        waiting &= ~(PartMask(1) << part);
      }
      const std::uint64_t blocked = packet_blocked(packet, counts, mailbox);
      for (int ray = 0; ray < packet.size; ++ray)
        if (!(blocked >> ray & 1)) visible |= PartMask(1) << packet.part[ray];
    }
    masks[k] = visible;
  }
}

}  // namespace ncube

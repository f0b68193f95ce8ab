#include "host/fast_octree.h"

#include <algorithm>
#include <cmath>

namespace ncube {

struct FastOctree::Packet {
  Vec3 from;
  int receiver_patch = -1, shooter_patch = -1;
  int flip = 0;  // the walk's child order: bit a set where the rays run downwards on axis a
  int size = 0;
  int part[kMaxShooterParts];
  Vec3 target[kMaxShooterParts];
  double target_on_axis[3][kMaxShooterParts];  // the same per axis, per ray
  double delta[3][kMaxShooterParts];  // per axis, per ray
};

struct FastOctree::Scratch {
  Scratch(std::size_t patches, int depth)
      : packet(patches, 0), tested(patches, 0),
        quotients(std::size_t(6 + 12 * (depth + 1)) * octree_lanes::kRays, 0.0) {}
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
  // Per ray (kRays each): the root's quotients of its lower (end 0) and upper (end 1) bound
  // on `axis`, and those of the four half bounds of the cell last split at `depth`
  // (octree_lanes::ChildrenQuery::quarters). Depth-first, a cell's children are all taken
  // before another cell of its depth is split, so its quotients are there when they are.
  double* root(int axis, int end) { return quotients.data() + std::size_t(2 * axis + end) * octree_lanes::kRays; }
  double* quarters(int depth, int axis) {
    return quotients.data() + std::size_t(6 + 12 * depth + 4 * axis) * octree_lanes::kRays;
  }
  std::vector<std::uint32_t> packet;
  std::vector<std::uint64_t> tested;
  std::uint32_t current = 0;
  std::vector<double> quotients;
};

FastOctree::FastOctree(std::unique_ptr<const Octree> octree, octree_lanes::Isa isa)
    : octree_(std::move(octree)), lanes_(octree_lanes::kernels(isa)), exact_(octree_->patches()) {
  // The depth of the deepest cell: children come after their parent in cells().
  const std::vector<Octree::Cell>& cells = octree_->cells();
  std::vector<int> depth(cells.size(), 0);
  for (std::size_t c = 0; c < cells.size(); ++c)
    if (cells[c].first_child >= 0)
      for (int k = 0; k < 8; ++k) depth[std::size_t(cells[c].first_child + k)] = depth[c] + 1;
  for (const int d : depth) depth_ = std::max(depth_, d);
}

namespace {

int direction_signs(const Vec3& delta) {
  return (delta.x < 0.0 ? 1 : 0) | (delta.y < 0.0 ? 2 : 0) | (delta.z < 0.0 ? 4 : 0);
}

}  // namespace

std::uint64_t FastOctree::packet_blocked(const Packet& packet, WorkCounts& counts,
                                         Scratch& scratch) const {
  const std::vector<Octree::Cell>& cells = octree_->cells();
  if (cells.empty()) return 0;
  scratch.next_packet();
  const std::vector<std::int32_t>& references = octree_->references();
  const std::vector<PatchCandidate>& patches = octree_->patches();
  // The root: visited by every ray, walked by those that meet it.
  counts.octree_cells_visited += std::uint64_t(packet.size);
  octree_lanes::RootQuery root{octree_->walk_bounds().data(), &packet.from.x,
                               {packet.delta[0], packet.delta[1], packet.delta[2]}, packet.size,
                               {scratch.root(0, 0), scratch.root(1, 0), scratch.root(2, 0)},
                               {scratch.root(0, 1), scratch.root(1, 1), scratch.root(2, 1)}};
  const std::uint64_t meets_root = lanes_.meets_root(root);
  if (meets_root == 0) return 0;
  // Depth-first as the walk. An entry is counted as visited, when popped, by the rays that
  // pushed it (`pushed_by`) and are still walking, as each of them counts the slab test of
  // every child it pops, met or missed; it is walked by the rays among them that meet it.
  // A child's own quotients are among those its parent's split wrote at the parent's depth
  // (`parent_depth`, -1 for the root: its own are scratch.root).
  struct Entry {
    std::int32_t cell;
    std::int16_t parent_depth;
    std::int16_t child;  // its index among its parent's children
    std::uint64_t pushed_by, met_by;
  };
  Entry stack[8 * 64 + 1];
  int top = 0;
  stack[top++] = Entry{0, -1, 0, 0, meets_root};  // the root's visit is counted above
  std::uint64_t blocked = 0;
  while (top > 0) {
    const Entry entry = stack[--top];
    counts.octree_cells_visited += std::uint64_t(__builtin_popcountll(entry.pushed_by & ~blocked));
    std::uint64_t rays = entry.met_by & ~blocked;
    if (rays == 0) continue;
    const Octree::Cell& cell = cells[std::size_t(entry.cell)];
    if (cell.first_child >= 0) {
      const int depth = entry.parent_depth + 1;
      const double* lower = octree_->walk_bounds().data() + 6 * std::size_t(cell.first_child);
      octree_lanes::ChildrenQuery query{lower, lower + 6 * 7, &packet.from.x,
                                        {packet.delta[0], packet.delta[1], packet.delta[2]},
                                        {}, {}, {}, rays};
      for (int axis = 0; axis < 3; ++axis) {
        if (entry.parent_depth < 0) {
          query.own_lo[axis] = scratch.root(axis, 0);
          query.own_hi[axis] = scratch.root(axis, 1);
        } else {
          const int half = entry.child >> axis & 1;
          const double* parent = scratch.quarters(entry.parent_depth, axis);
          query.own_lo[axis] = parent + (2 * half) * octree_lanes::kRays;
          query.own_hi[axis] = parent + (2 * half + 1) * octree_lanes::kRays;
        }
        query.quarters[axis] = scratch.quarters(depth, axis);
      }
      std::uint64_t met[8];
      lanes_.children_met(query, met);
      for (int k = 7; k >= 0; --k) {
        const int child = k ^ packet.flip;
        stack[top++] = Entry{cell.first_child + child, std::int16_t(depth), std::int16_t(child),
                             rays, met[child]};  // first on top
      }
      continue;
    }
    for (std::int32_t i = cell.patch_begin; i < cell.patch_begin + cell.patch_count; ++i) {
      const std::int32_t position = references[std::size_t(i)];
      std::uint64_t& tested = scratch.rays(std::size_t(position));
      const std::uint64_t asking = rays & ~tested;  // each ray tests a patch once
      if (asking == 0) continue;
      tested |= asking;
      const PatchCandidate& c = patches[std::size_t(position)];
      if (c.scene_index == packet.receiver_patch || c.scene_index == packet.shooter_patch) continue;
      const double tolerance = octree_->side_tolerance();
      const int side_of_from = exact_.side(position, packet.from, tolerance);
      counts.ray_patch_tests += std::uint64_t(__builtin_popcountll(asking));
      if (exact_.fast(position)) {  // eight rays at a time
        const AxisPatchTest::Record& r = exact_.record(position);
        const octree_lanes::LeafQuery query{
            r.axis, r.edges, r.other, r.normal, r.offset, r.signed_length, r.corner,
            &packet.from.x, {packet.delta[0], packet.delta[1], packet.delta[2]},
            packet.target_on_axis[r.axis], tolerance, side_of_from, asking};
        const octree_lanes::LeafAnswer answer = lanes_.leaf_tests(query);
        counts.plane_crossings += std::uint64_t(__builtin_popcountll(answer.crossing));
        blocked |= answer.blocked;  // the first blocker ends a ray's walk
        rays &= ~answer.blocked;
        if (rays == 0) break;
        continue;
      }
      for (std::uint64_t left = asking; left != 0; left &= left - 1) {
        const int ray = __builtin_ctzll(left);
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
  Scratch scratch(octree_->patches().size(), depth_);
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
        for (int axis = 0; axis < 3; ++axis) packet.target_on_axis[axis][ray] = shooter.targets[part][axis];
        for (int axis = 0; axis < 3; ++axis) packet.delta[axis][ray] = delta[axis];
        waiting &= ~(PartMask(1) << part);
      }
      const std::uint64_t blocked = packet_blocked(packet, counts, scratch);
      for (int ray = 0; ray < packet.size; ++ray)
        if (!(blocked >> ray & 1)) visible |= PartMask(1) << packet.part[ray];
    }
    masks[k] = visible;
  }
}

}  // namespace ncube

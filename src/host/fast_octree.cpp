#include "host/fast_octree.h"

#include <algorithm>
#include <cmath>

#include "host/lookahead.h"

namespace ncube {

struct FastOctree::Packet {
  Vec3 from;
  int receiver_patch = -1, shooter_patch = -1;
  int flip = 0;  // the walk's child order: bit a set where the rays run downwards on axis a
  int size = 0;
  // Per ray: the shooter's part (null: ray r is part r), and per axis (kMaxShooterParts
  // each) the target's coordinate and target - from.
  const int* part = nullptr;
  const double* target_on_axis[3];
  const double* delta[3];
};

namespace {

// The bits set in x. Without POPCNT in the baseline instruction set, __builtin_popcountll is a
// call into libgcc; this is the same count in a dozen instructions inline.
inline std::uint64_t bit_count(std::uint64_t x) {
#ifdef __POPCNT__
  return std::uint64_t(__builtin_popcountll(x));
#else
  x -= (x >> 1) & 0x5555555555555555ull;
  x = (x & 0x3333333333333333ull) + ((x >> 2) & 0x3333333333333333ull);
  x = (x + (x >> 4)) & 0x0f0f0f0f0f0f0f0full;
  return (x * 0x0101010101010101ull) >> 56;
#endif
}

}  // namespace

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
    counts.octree_cells_visited += bit_count(entry.pushed_by & ~blocked);
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
      counts.ray_patch_tests += bit_count(asking);
      if (exact_.fast(position)) {  // eight rays at a time
        const AxisPatchTest::Record& r = exact_.record(position);
        const octree_lanes::LeafQuery query{
            r.axis, r.edges, r.other, r.normal, r.offset, r.signed_length, r.corner,
            &packet.from.x, {packet.delta[0], packet.delta[1], packet.delta[2]},
            packet.target_on_axis[r.axis], tolerance, side_of_from, asking};
        const octree_lanes::LeafAnswer answer = lanes_.leaf_tests(query);
        counts.plane_crossings += bit_count(answer.crossing);
        blocked |= answer.blocked;  // the first blocker ends a ray's walk
        rays &= ~answer.blocked;
        if (rays == 0) break;
        continue;
      }
      for (std::uint64_t left = asking; left != 0; left &= left - 1) {
        const int ray = __builtin_ctzll(left);
        const Vec3 target(packet.target_on_axis[0][ray], packet.target_on_axis[1][ray],
                          packet.target_on_axis[2][ray]);
        if (side_of_from * exact_.side(position, target, tolerance) < 0)
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
  if (lookahead_ && lookahead_->answers(*this, shooter, block, masks, counts)) return;
  answer_block_here(block, shooter, masks, counts);
}

void FastOctree::answer_block_here(const PointBlock& block, const Shooter& shooter,
                                   PartMask* masks, WorkCounts& counts) const {
  std::unique_ptr<Scratch> scratch = take_scratch();
  const int m = shooter.part_count;
  const PartMask all = shooter.all_parts();
  alignas(64) double targets[3][kMaxShooterParts] = {};  // the shooter's, per axis
  alignas(64) double delta[3][kMaxShooterParts];    // a point's rays, per axis
  alignas(64) double gathered_targets[3][kMaxShooterParts], gathered_delta[3][kMaxShooterParts];
  int gathered_part[kMaxShooterParts];
  for (int part = 0; part < m; ++part)
    for (int axis = 0; axis < 3; ++axis) targets[axis][part] = shooter.targets[part][axis];
  Packet packet;
  packet.shooter_patch = shooter.patch;
  for (std::size_t k = 0; k < block.count; ++k) {
    packet.from = block.points[k];
    packet.receiver_patch = block.patches[k];
    counts.rays += std::uint64_t(m);
    // The rays' deltas (target - point, as the walk's) and which run downwards per axis.
    octree_lanes::RaysQuery rays{{targets[0], targets[1], targets[2]}, &packet.from.x, m,
                                 {delta[0], delta[1], delta[2]}, {}};
    lanes_.rays(rays);
    const PartMask* downwards = rays.downwards;
    if ((downwards[0] == 0 || downwards[0] == all) && (downwards[1] == 0 || downwards[1] == all) &&
        (downwards[2] == 0 || downwards[2] == all)) {  // one packet: every ray the same signs
      packet.flip = (downwards[0] ? 1 : 0) | (downwards[1] ? 2 : 0) | (downwards[2] ? 4 : 0);
      packet.size = m;
      packet.part = nullptr;
      for (int axis = 0; axis < 3; ++axis) {
        packet.target_on_axis[axis] = targets[axis];
        packet.delta[axis] = delta[axis];
      }
      masks[k] = all & ~packet_blocked(packet, counts, *scratch);
      continue;
    }
    int signs[kMaxShooterParts];
    for (int part = 0; part < m; ++part)
      signs[part] = int(downwards[0] >> part & 1) | int(downwards[1] >> part & 1) << 1 |
                    int(downwards[2] >> part & 1) << 2;
    for (int axis = 0; axis < 3; ++axis) {
      packet.target_on_axis[axis] = gathered_targets[axis];
      packet.delta[axis] = gathered_delta[axis];
    }
    packet.part = gathered_part;
    PartMask waiting = all, visible = 0;
    while (waiting != 0) {  // one packet per direction signs, in the order of their first part
      packet.flip = signs[__builtin_ctzll(waiting)];
      packet.size = 0;
      for (PartMask left = waiting; left != 0; left &= left - 1) {
        const int part = __builtin_ctzll(left);
        if (signs[part] != packet.flip) continue;
        const int ray = packet.size++;
        gathered_part[ray] = part;
        for (int axis = 0; axis < 3; ++axis) {
          gathered_targets[axis][ray] = targets[axis][part];
          gathered_delta[axis][ray] = delta[axis][part];
        }
        waiting &= ~(PartMask(1) << part);
      }
      const std::uint64_t blocked = packet_blocked(packet, counts, *scratch);
      for (int ray = 0; ray < packet.size; ++ray)
        if (!(blocked >> ray & 1)) visible |= PartMask(1) << gathered_part[ray];
    }
    masks[k] = visible;
  }
  give_back(scratch);
}

std::unique_ptr<FastOctree::Scratch> FastOctree::take_scratch() const {
  {
    const std::lock_guard<std::mutex> lock(spare_mutex_);
    if (!spare_.empty()) {
      std::unique_ptr<Scratch> scratch = std::move(spare_.back());
      spare_.pop_back();
      return scratch;
    }
  }
  return std::make_unique<Scratch>(octree_->patches().size(), depth_);
}

void FastOctree::give_back(std::unique_ptr<Scratch>& scratch) const {
  const std::lock_guard<std::mutex> lock(spare_mutex_);
  spare_.push_back(std::move(scratch));
}

FastOctree::~FastOctree() = default;

}  // namespace ncube

// The octree walk of section 6 (visibility/octree.h), faster on the host: the rays from one
// point to the shooter's parts walk the tree together, as a packet. Rays whose directions
// have the same signs take the cells in the same depth-first order (the walk's order
// depends on the signs only), so one walk of the tree, with a mask of the rays still
// walking, visits each cell for exactly the rays whose own walks would visit it: a cell is
// counted for the rays that pushed it and have not yet found a blocker when it is popped, a
// leaf's patches are tested in list order for the rays that met the leaf, each ray's mailbox
// is a bit per patch, and a ray leaves the packet at its first blocker. Per cell, the 8
// children's slab intervals are found per axis and half (the children share their bounds
// with their parent's halves), eight rays at a time, from the quotients of the parent's own
// bounds and two new ones per axis (octree_lanes.h).
//
// Contract (host side): it changes no answer and no count. A child's test combines the very
// doubles the walk's slab test computes (the same stored bounds, the same expressions; max and
// min are exact), so each child is met or missed for each ray as in the walk; every mask and
// counter equals Octree's (tests/fast_octree_test.cpp on every scene, and whole result files
// against --reference-visibility in tests/seam_test.sh).
#pragma once

#include <memory>
#include <mutex>
#include <vector>

#include "host/axis_patch_test.h"
#include "host/host_side.h"
#include "host/octree_lanes.h"
#include "visibility/octree.h"

namespace ncube {

class Lookahead;

class FastOctree : public OccluderSet {
 public:
  // `isa`: which compiled variant of the slab tests runs (all give the same bits; tests
  // choose each in turn).
  explicit FastOctree(std::unique_ptr<const Octree> octree,
                      octree_lanes::Isa isa = octree_lanes::best_isa());
  ~FastOctree() override;

  // The walk's answers and counts for a block: from the host threads computing ahead when
  // the block was posted to them (lookahead.h), else computed here.
  void unblocked_parts(const PointBlock& block, const Shooter& shooter, PartMask* masks,
                       WorkCounts& counts) const override;
  using OccluderSet::unblocked_parts;
  // The same computed on the calling thread (safe on several threads at once).
  void answer_block_here(const PointBlock& block, const Shooter& shooter, PartMask* masks,
                         WorkCounts& counts) const;
  // From now on the batch call first asks `lookahead` (not owned; null: none).
  void use_lookahead(Lookahead* lookahead) { lookahead_ = lookahead; }
  WorkCounts build_work() const override { return octree_->build_work(); }
  const std::vector<int>& patch_indices() const override { return octree_->patch_indices(); }

  struct Packet;   // rays from one point whose directions have the same signs
  struct Scratch;  // per patch, the packet's rays that have tested it; the rays' quotients

 private:
  // The packet's rays that meet a blocker (bit i: the packet's ray i).
  std::uint64_t packet_blocked(const Packet& packet, WorkCounts& counts, Scratch& scratch) const;
  // A scratch for one block's walks: one given back before, or a new one. Reusing one is
  // safe: its mailbox stamps only grow, and its quotients are written before they are read.
  std::unique_ptr<Scratch> take_scratch() const;
  void give_back(std::unique_ptr<Scratch>& scratch) const;

  std::unique_ptr<const Octree> octree_;
  octree_lanes::Kernels lanes_;
  int depth_ = 0;  // of the deepest cell (the root is 0)
  Lookahead* lookahead_ = nullptr;
  mutable std::mutex spare_mutex_;
  mutable std::vector<std::unique_ptr<Scratch>> spare_;
  AxisPatchTest exact_;  // the leaves' exact tests and side tests, fewer operations
};

}  // namespace ncube

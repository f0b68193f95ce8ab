// The octree walk of section 6 (visibility/octree.h), faster on the host: the rays from one
// point to the shooter's parts walk the tree together, as a packet. Rays whose directions
// have the same signs take the cells in the same depth-first order (the walk's order
// depends on the signs only), so one walk of the tree, with a mask of the rays still
// walking, visits each cell for exactly the rays whose own walks would visit it: a cell is
// counted for the rays that pushed it and have not yet found a blocker when it is popped, a
// leaf's patches are tested in list order for the rays that met the leaf, each ray's mailbox
// is a bit per patch, and a ray leaves the packet at its first blocker. Per cell, the 8
// children's slab intervals are found per axis and half (the children share their bounds
// with their parent's halves) from numerators shared by the packet's rays.
//
// Contract (host side): it changes no answer and no count. A child's test combines the very
// doubles the walk's slab test computes (the same stored bounds, the same expressions; max and
// min are exact), so each child is met or missed for each ray as in the walk; every mask and
// counter equals Octree's (tests/fast_octree_test.cpp on every scene, and whole result files
// against --reference-visibility in tests/seam_test.sh).
#pragma once

#include <memory>

#include "host/axis_patch_test.h"
#include "host/host_side.h"
#include "visibility/octree.h"

namespace ncube {

class FastOctree : public OccluderSet {
 public:
  explicit FastOctree(std::unique_ptr<const Octree> octree)
      : octree_(std::move(octree)), exact_(octree_->patches()) {}

  void unblocked_parts(const PointBlock& block, const Shooter& shooter, PartMask* masks,
                       WorkCounts& counts) const override;
  using OccluderSet::unblocked_parts;
  WorkCounts build_work() const override { return octree_->build_work(); }
  const std::vector<int>& patch_indices() const override { return octree_->patch_indices(); }

  struct Packet;   // rays from one point whose directions have the same signs
  struct Mailbox;  // per patch, the packet's rays that have tested it

 private:
  // The packet's rays that meet a blocker (bit i: the packet's ray i).
  std::uint64_t packet_blocked(const Packet& packet, WorkCounts& counts, Mailbox& mailbox) const;
  // The packet's rays that meet the root cell.
  std::uint64_t meets_root_cell(const Packet& packet) const;
  // For each child of inner cell `cell` (by child index), which of `rays` meet it.
  void children_met(const Octree::Cell& cell, const Packet& packet, std::uint64_t rays,
                    std::uint64_t met[8]) const;

  std::unique_ptr<const Octree> octree_;
  AxisPatchTest exact_;  // the leaves' exact tests and side tests, fewer operations
};

}  // namespace ncube

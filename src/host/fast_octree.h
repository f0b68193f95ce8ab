// The octree walk of section 6 (visibility/octree.h), faster on the host: when the walk meets
// an inner cell, it slab-tests the 8 children; here the children's slab intervals are found
// per axis and half (the children share their bounds with their parent's halves), 12
// divisions instead of 48, and the 8 tests are combined from them. The children are still
// taken in the walk's order, each one counted as visited when the walk would pop it, and
// the leaves' patches tested in their lists' order with the same mailbox, so the walk stops
// at the same first blocker.
//
// Contract (host side): it changes no answer and no count. A child's test combines the very
// doubles the walk's slab test computes (the same stored bounds, the same expressions; max and
// min are exact), so each child is met or missed as in the walk; every mask and counter equals
// Octree's (tests/fast_octree_test.cpp on every scene, and whole result files against
// --reference-visibility in tests/seam_test.sh).
#pragma once

#include <memory>

#include "host/host_side.h"
#include "visibility/octree.h"

namespace ncube {

class FastOctree : public OccluderSet {
 public:
  explicit FastOctree(std::unique_ptr<const Octree> octree) : octree_(std::move(octree)) {}

  void unblocked_parts(const PointBlock& block, const Shooter& shooter, PartMask* masks,
                       WorkCounts& counts) const override;
  using OccluderSet::unblocked_parts;
  WorkCounts build_work() const override { return octree_->build_work(); }
  const std::vector<int>& patch_indices() const override { return octree_->patch_indices(); }

 private:
  bool ray_blocked(const Vec3& from, const Vec3& target, int receiver_patch, int shooter_patch,
                   WorkCounts& counts, Octree::Scratch& scratch) const;
  // Which of inner cell `cell`'s children (by child index) the segment meets.
  unsigned children_met(const Octree::Cell& cell, const Vec3& from, const Vec3& delta) const;

  std::unique_ptr<const Octree> octree_;
};

}  // namespace ncube

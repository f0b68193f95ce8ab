// Any occluder set (visibility/occluder_set.h) with a block's points shared out over host
// threads: the octree walk of section 6, whose points are independent of one another.
//
// Contract (host side): it changes no answer and no count. Each point's mask is the wrapped
// set's for that point; the counts are integer sums over the points, the same in any order
// (tests/octree_test.cpp; whole result files against --reference-visibility in
// tests/seam_test.sh).
#pragma once

#include <memory>

#include "host/host_side.h"
#include "visibility/occluder_set.h"

namespace ncube {

class ThreadedOccluders : public OccluderSet {
 public:
  // `threads`: as --threads (0: every core).
  ThreadedOccluders(std::unique_ptr<const OccluderSet> set, int threads)
      : set_(std::move(set)), threads_(threads) {}

  void unblocked_parts(const PointBlock& block, const Shooter& shooter, PartMask* masks,
                       WorkCounts& counts) const override;
  using OccluderSet::unblocked_parts;
  WorkCounts build_work() const override { return set_->build_work(); }
  const std::vector<int>& patch_indices() const override { return set_->patch_indices(); }

 private:
  std::unique_ptr<const OccluderSet> set_;
  int threads_;
};

}  // namespace ncube

// What a visibility test *is* in the simulated program (sections 2.2, 3 and 6): a node holds
// a set of patches (all of the scene's on a radiosity processor without visibility
// processors, a 1/V share on a visibility processor) and answers, for a block of points and
// the shooter, which parts of the shooter each point sees past the set's patches, and what
// finding that out cost the node (the counts it is charged for).
//
// The readable definitions are the paper's brute-force loop (brute_force_occluders.h) and the
// octree walk of section 6 (octree.h). The host computes the same answers and the same counts
// faster behind this interface (src/host/: fast_occluders.h for the loop, fast_octree.h for
// the walk, threaded_occluders.h sharing a set's points over threads); those implementations
// may change no answer and no count, and `--reference-visibility` runs the readable
// definitions alone so that whole result files can be compared (tests/seam_test.sh).
#pragma once

#include <vector>

#include "counts/held_items.h"
#include "counts/work_counts.h"
#include "visibility/point_block.h"
#include "visibility/shooter.h"

namespace ncube {

// How far the brute-force loop runs for one ray (a model choice the paper leaves open).
enum class RayTestPolicy {
  kTestAllPatches,        // "each ray is intersected with all other patches" (default)
  kStopAtFirstBlocker,    // the loop ends at the first patch, in set order, that blocks
};

// Each readable definition is registered once as a visibility method (visibility_methods.h).
class OccluderSet {
 public:
  virtual ~OccluderSet() = default;

  // masks[k], for k < block.count: bit p is set when the segment from block.points[k] to
  // the shooter's part p crosses none of this set's patches other than block.patches[k]
  // and the shooter itself. Adds the work the node program does to find out to `counts`.
  virtual void unblocked_parts(const PointBlock& block, const Shooter& shooter, PartMask* masks,
                               WorkCounts& counts) const = 0;
  // The work of building the set's search structure, charged once when the node program
  // starts (none for the brute-force loop).
  virtual WorkCounts build_work() const { return {}; }
  // What a node holds for the set's search structure beside the patches' geometry (which
  // every method needs and memory_plan.h counts), in items the cost model weighs: none for
  // the brute-force loop.
  virtual HeldItems structure_items() const { return {}; }
  // The scene patches of the set, in the order the loop (or the octree's leaves) lists them.
  virtual const std::vector<int>& patch_indices() const = 0;

  int size() const { return int(patch_indices().size()); }
  // One point.
  PartMask unblocked_parts(const Vec3& point, int receiver_patch, const Shooter& shooter,
                           WorkCounts& counts) const {
    PartMask mask = 0;
    unblocked_parts(PointBlock(&point, &receiver_patch, 1), shooter, &mask, counts);
    return mask;
  }
};

// Adds to counts.blocked_rays the rays of a block's answers that found their part blocked
// (NCUBE_HOST_WORK_COUNTERS): read from the answers, so that every way of finding them (the
// readable definitions and the host's) counts the same. The node programs call it beside
// unblocked_parts (visible_parts, the visibility processor).
inline void count_blocked_rays(const PartMask* masks, std::size_t count, const Shooter& shooter,
                               WorkCounts& counts) {
  const PartMask all = shooter.all_parts();
  std::uint64_t blocked = 0;
  for (std::size_t k = 0; k < count; ++k)
    blocked += std::uint64_t(shooter.part_count - __builtin_popcountll(masks[k] & all));
  counts.blocked_rays += blocked;
}

}  // namespace ncube

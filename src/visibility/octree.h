// Octree visibility (section 6: "We are currently implementing an octree method to improve
// the performance of the visibility tests"), a simulated option beside the paper's
// brute-force loop (brute_force_occluders.h). A node builds an octree over the patches it holds and walks
// each shadow ray through the cells it meets, front to back, testing each patch of a visited
// leaf once (mailbox) with the exact ray-patch test, and stops at the first blocker. The
// answers are those of the brute-force loop; the counts are the walk's own (what the nCube2
// program would do), not the brute-force loop's. docs/model.md, "Octree visibility".
#pragma once

#include <cstdint>
#include <vector>

#include "scene/scene.h"
#include "visibility/occluder_set.h"
#include "visibility/ray_patch_test.h"

namespace ncube {

// Build parameters (a model choice; the paper gives none).
struct OctreeParameters {
  int max_depth = 8;         // the root is depth 0; cells at this depth are never split
  int max_leaf_patches = 8;  // a cell with more patches is split into 8 halves
};

// What building the octree costs, counted as the node program would do it.
struct OctreeBuildCounts {
  std::uint64_t overlap_tests = 0;  // patch box against child cell box, 8 per patch of a split cell
  std::uint64_t cells = 0;          // cells created (root included)
  std::uint64_t patch_references = 0;  // entries of the leaves' patch lists
  std::uint64_t leaves = 0;
};

class Octree : public OccluderSet {
 public:
  // `patch_indices` are scene patch indices in the order the leaves list them.
  Octree(const Scene& scene, const std::vector<int>& patch_indices, OctreeParameters parameters = {});

  // Scratch of one host thread: the mailbox (the ray each patch was last tested for).
  struct Scratch {
    std::vector<std::uint32_t> tested_for_ray;
    std::uint32_t ray = 0;
  };
  Scratch make_scratch() const { return Scratch{std::vector<std::uint32_t>(patches_.size(), 0), 0}; }

  // Bit p is set when the segment from `point` to the shooter's part p crosses none of the
  // set's patches other than `receiver_patch` and the shooter (the brute-force loop's answer).
  // Adds the rays, cells visited (slab tests), ray-patch tests and plane crossings of the walk.
  PartMask unblocked_parts(const Vec3& point, int receiver_patch, const Shooter& shooter,
                           WorkCounts& counts, Scratch& scratch) const;

  // The same for a block of points, one after the other with one mailbox.
  void unblocked_parts(const PointBlock& block, const Shooter& shooter, PartMask* masks,
                       WorkCounts& counts) const override;
  using OccluderSet::unblocked_parts;
  // Building it: the overlap tests and the cells made.
  WorkCounts build_work() const override;
  // Its cells and the leaves' patch lists, at the cost model's sizes (section 6: a node that
  // tests rays holds the octree over its set).
  HeldItems structure_items() const override;
  const std::vector<int>& patch_indices() const override { return patch_indices_; }

  const OctreeBuildCounts& build_counts() const { return build_; }

  // Read-only views of the tree, for faster walks that must count as this one does
  // (src/host/fast_octree.h).
  struct Cell {
    Vec3 lo, hi;
    std::int32_t first_child = -1;  // the 8 children are cells first_child .. first_child + 7;
                                    // child index bit 0: upper x half, bit 1: y, bit 2: z
    std::int32_t patch_begin = 0, patch_count = 0;  // a leaf's positions in references_
  };
  const std::vector<Cell>& cells() const { return cells_; }
  const std::vector<double>& walk_bounds() const { return walk_bounds_; }
  const std::vector<std::int32_t>& references() const { return references_; }
  const std::vector<PatchCandidate>& patches() const { return patches_; }
  // The walk's two tests: does the segment from + t delta, t in [0, 1], meet the cell (grown
  // by the pad), and on which side of a patch's plane a point lies (+1, -1, 0).
  bool segment_meets_cell(int cell, const Vec3& from, const Vec3& delta) const;
  double side_tolerance() const { return side_tolerance_; }
  int side_of(const PatchCandidate& c, const Vec3& x) const {
    const double distance = glm::dot(c.normal, x) - c.plane_offset;
    return distance > side_tolerance_ ? 1 : (distance < -side_tolerance_ ? -1 : 0);
  }

 private:
  void split(int cell, std::vector<std::int32_t> patches, int depth);
  bool ray_blocked(const Vec3& from, const Vec3& target, int receiver_patch, int shooter_patch,
                   WorkCounts& counts, Scratch& scratch) const;

  OctreeParameters parameters_;
  std::vector<int> patch_indices_;
  std::vector<PatchCandidate> patches_;      // by position in the set
  std::vector<Vec3> box_lo_, box_hi_;        // per position: bounding box grown by pad_
  std::vector<Cell> cells_;                  // cells_[0] is the root
  std::vector<double> walk_bounds_;          // per cell: lo x, y, z, hi x, y, z grown by pad_
                                             // (stored grown once, as the nCube2 program would)
  std::vector<std::int32_t> references_;     // leaves' patch lists (positions)
  double pad_ = 0.0;             // boxes grow by this, so rounding never loses a hit
  double side_tolerance_ = 0.0;  // as the brute-force loop's (plane_side_tolerance)
  OctreeBuildCounts build_;
};

}  // namespace ncube

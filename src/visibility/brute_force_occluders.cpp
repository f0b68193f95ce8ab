#include "visibility/brute_force_occluders.h"

namespace ncube {

BruteForceOccluders::BruteForceOccluders(const Scene& scene, std::vector<int> patch_indices,
                                         RayTestPolicy policy)
    : policy_(policy), patch_indices_(std::move(patch_indices)) {
  side_tolerance_ = plane_side_tolerance(scene);
  patches_.reserve(patch_indices_.size());
  for (int scene_index : patch_indices_) {
    const Patch& p = scene.patches[std::size_t(scene_index)];
    patches_.push_back(make_candidate(p.polygon, p.normal, scene_index));
  }
}

void BruteForceOccluders::unblocked_parts(const PointBlock& block, const Shooter& shooter,
                                          PartMask* masks, WorkCounts& counts) const {
  for (std::size_t k = 0; k < block.count; ++k)
    masks[k] = answer(block.points[k], block.patches[k], shooter, counts);
}

PartMask BruteForceOccluders::answer(const Vec3& point, int receiver_patch, const Shooter& shooter,
                                     WorkCounts& counts) const {
  PartMask visible = 0;
  for (int part = 0; part < shooter.part_count; ++part) {
    const Vec3& target = shooter.targets[part];
    const Vec3 delta = target - point;
    bool blocked = false;
    for (const PatchCandidate& c : patches_) {
      // A ray does not test the patch it starts on nor the shooter it ends on.
      if (c.scene_index == receiver_patch || c.scene_index == shooter.patch) continue;
      ++counts.ray_patch_tests;
      if (side_of(c, point) * side_of(c, target) < 0) ++counts.plane_crossings;
      if (segment_crosses(c, point, delta)) {
        blocked = true;
        if (policy_ == RayTestPolicy::kStopAtFirstBlocker) break;
      }
    }
    ++counts.rays;
    if (!blocked) visible |= PartMask(1) << part;
  }
  return visible;
}

}  // namespace ncube

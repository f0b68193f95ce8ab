// The paper's visibility test, literally (section 2.2: "each ray is intersected with all
// other patches"): for every point and every part of the shooter, a ray, tested against
// each patch of the set in order with the exact test of ray_patch_test.h. This is the
// definition of the answers and of the counts charged for the brute-force method; the host's
// fast implementation (src/host/fast_occluders.h) must give both bit for bit.
#pragma once

#include <vector>

#include "scene/scene.h"
#include "visibility/occluder_set.h"
#include "visibility/ray_patch_test.h"

namespace ncube {

class BruteForceOccluders : public OccluderSet {
 public:
  // `patch_indices`: scene patch indices in the order the loop visits them.
  BruteForceOccluders(const Scene& scene, std::vector<int> patch_indices, RayTestPolicy policy);

  void unblocked_parts(const PointBlock& block, const Shooter& shooter, PartMask* masks,
                       WorkCounts& counts) const override;
  using OccluderSet::unblocked_parts;
  const std::vector<int>& patch_indices() const override { return patch_indices_; }

 private:
  // One point: the loop over the parts and, for each ray, over the set's patches. Counts a
  // ray per part, a test per patch tried, and a plane crossing per test whose ray's two
  // ends lie strictly on opposite sides of the patch's plane (only then does the test go
  // on to the hit point and the edge tests).
  PartMask answer(const Vec3& point, int receiver_patch, const Shooter& shooter,
                  WorkCounts& counts) const;
  // +1, -1 or 0 (within the tolerance) for a point and a patch's plane.
  int side_of(const PatchCandidate& c, const Vec3& x) const {
    const double distance = c.normal.x * x.x + c.normal.y * x.y + c.normal.z * x.z - c.plane_offset;
    return distance > side_tolerance_ ? 1 : (distance < -side_tolerance_ ? -1 : 0);
  }

  RayTestPolicy policy_;
  std::vector<int> patch_indices_;
  std::vector<PatchCandidate> patches_;  // in loop order
  double side_tolerance_ = 0.0;          // distances within this count as "on the plane"
};

}  // namespace ncube

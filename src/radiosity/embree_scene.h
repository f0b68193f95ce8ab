// The patches of an occluder set as an Embree scene (Intel's ray-tracing kernels, Debian
// libembree-dev 3.13), used to answer "which of these rays are blocked" at ray-tracing-library
// speed while the exact double test of ray_patch_test.h decides every answer.
//
// Embree works in single precision. To stay exact it is made conservative, and it only
// proposes: every patch goes in as a quad padded outwards in its plane, every ray starts a
// little before its visibility point and ends a little past its target, so every crossing the
// exact test would find is among the hits Embree reports; an occlusion filter then runs the
// exact test on each reported hit and rejects those the exact test denies (and the excluded
// receiver and shooter patches). Embree does the traversal, the exact test decides
// (docs/performance.md).
#pragma once

#include <embree3/rtcore.h>

#include <vector>

#include "radiosity/ray_patch_test.h"
#include "radiosity/shooter.h"

namespace ncube {

class EmbreeScene {
 public:
  // `candidates` (kept by reference: must outlive this scene) in their set order; `pad` is
  // the margin (scene units) by which quads are grown and rays lengthened, far above the
  // single-precision rounding of the scene's coordinates.
  EmbreeScene(const std::vector<PatchCandidate>& candidates, double pad);
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  // Bit k is set when the segment from `from` to `targets[k]` (k < count <= 64) crosses, by
  // the exact test, a candidate other than the positions `excluded_a` and `excluded_b`
  // (-1: none). Safe to call from several threads at once.
  PartMask blocked(const Vec3& from, const Vec3* targets, int count, int excluded_a,
                   int excluded_b) const;

  // Every candidate (not excluded) the segment to targets[k] crosses by the exact test:
  // appends (k, position) pairs to `hits`, in no particular order. Every hit along each
  // segment is examined (no early end).
  void all_blockers(const Vec3& from, const Vec3* targets, int count, int excluded_a,
                    int excluded_b, std::vector<std::pair<int, int>>& hits) const;

 private:
  struct Query;
  static void exact_filter(const RTCFilterFunctionNArguments* args);
  void prepare(Query& query, const Vec3& from, const Vec3* targets, int count, int excluded_a,
               int excluded_b) const;
  PartMask trace(Query& query, int count) const;  // rays Embree reports blocked

  const std::vector<PatchCandidate>& candidates_;
  double pad_;
  RTCScene scene_ = nullptr;
};

}  // namespace ncube

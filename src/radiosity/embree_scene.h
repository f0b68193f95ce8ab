// The patches of an occluder set as an Embree scene (Intel's ray-tracing kernels, Debian
// libembree-dev 3.13), used to answer "which of these rays are blocked" at ray-tracing-library
// speed while the exact double test of ray_patch_test.h decides every answer.
//
// Embree works in single precision. To stay exact it only proposes, conservatively: every
// patch goes in as a quad grown by `pad` in its plane, every ray starts `pad` before its
// visibility point and ends `pad` past its target, so every crossing the exact test would
// find is among the hits Embree reports; an occlusion filter runs the exact test on each
// reported hit and rejects those the exact test denies (and the excluded receiver and
// shooter patches, which every ray meets). Embree does the traversal, the exact test
// decides. Rays nearly parallel to a plane are the caller's (occluders.h): there single
// precision cannot be trusted at any padding (docs/performance.md).
#pragma once

#include <embree3/rtcore.h>

#include <cstdint>
#include <utility>
#include <vector>

#include "radiosity/ray_patch_test.h"
#include "radiosity/shooter.h"

namespace ncube {

class EmbreeScene {
 public:
  // `candidates` (kept by reference: must outlive this scene) in their set order; `pad` is
  // the margin (scene units) of the quads and of the rays' ends, far above the
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
  // appends (k, position) pairs to `hits`, in no particular order, possibly twice (Embree
  // meets a quad as two triangles). Every hit along each segment is examined (no early end).
  void all_blockers(const Vec3& from, const Vec3* targets, int count, int excluded_a,
                    int excluded_b, std::vector<std::pair<int, int>>& hits) const;

  // Sets of candidates (up to 64, `sets_of[position]`: bit s set when the candidate is in
  // set s): ray_sets[k] gets the sets holding a candidate (not excluded) the segment to
  // targets[k] crosses by the exact test. A hit whose sets are all known already is not
  // tested, and a ray ends once it has found all of `all_sets`.
  void blocked_sets(const Vec3& from, const Vec3* targets, int count, int excluded_a,
                    int excluded_b, const std::uint64_t* sets_of, std::uint64_t all_sets,
                    std::uint64_t* ray_sets) const;

 private:
  struct Query;
  static void exact_filter(const RTCFilterFunctionNArguments* args);
  void prepare(Query& query, const Vec3& from, const Vec3* targets, int count, int excluded_a,
               int excluded_b, std::vector<std::pair<int, int>>* hits) const;
  // The rays through Embree: returns those reported blocked.
  PartMask trace(Query& query, int count) const;

  const std::vector<PatchCandidate>& candidates_;
  double pad_;
  RTCScene scene_ = nullptr;
};

}  // namespace ncube

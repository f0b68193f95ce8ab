// The patches of an occluder set as an Embree scene (Intel's ray-tracing kernels, Debian
// libembree-dev 3.13), used to answer "which of these rays are blocked" at ray-tracing-library
// speed while the exact double test of ray_patch_test.h decides every answer.
//
// Embree works in single precision. To stay exact it only proposes, conservatively: every
// patch goes in as triangles covering it grown by `pad` in its plane, each crossing of the
// patch at least `pad` inside one of them, so every crossing the exact test would find in
// the part of a ray Embree is asked about is among the hits Embree reports; an occlusion
// filter runs the exact test on each reported hit and rejects those the exact test denies
// (and the excluded receiver and shooter patches). Embree does the traversal, the exact test
// decides. Rays nearly parallel to a plane are the caller's (fast_occluders.h): there single
// precision cannot be trusted at any padding (docs/performance.md). With that margin
// everywhere, Embree's faster non-robust mode suffices: its triangle test is not watertight
// (a ray along an edge shared by two triangles may miss both), but no crossing lies within
// rounding distance of an edge of the triangle it is `pad` inside of; its box tests round
// each bound monotonically and a flat box's two bounds alike (docs/performance.md).
//
// The ends of a ray are not Embree's: it is asked about the ray from kEndGap pads past its
// point to kEndGap pads short of its target, so it does not meet the receiver's and the
// shooter's own patches, which every ray starts and ends on (three quarters of the hits it
// handed to the filter when rays reached a pad beyond both ends). The exact test runs
// instead, for every ray of an end, on the patches near that end (near_patches.h: their
// bounding box grown by kNearRadius pads holds it). Why no crossing is missed, for a ray
// of length L and an exact crossing at distance d from its point (along the ray):
//  * d <= kNearRadius pads (less double rounding): the crossing point is on the patch and
//    within that distance of the point in every coordinate, so the point is in the patch's
//    grown box: the patch is near the point and gets the exact test. L - d likewise: near
//    the target.
//  * otherwise the crossing lies more than kNearRadius - kEndGap = 1.5 pads inside the part
//    of the ray Embree is asked about, more than the single-precision error of Embree's hit
//    parameter there: at most a pad (rounding of about 1e-6 of the scale over the sine of
//    the crossing angle, above SceneBlockers::kBand for every crossing left to Embree: the
//    budget the triangles' padding covers in their plane, and the old rays' reach past both
//    ends along the ray; docs/performance.md). Embree reports it, and the filter's exact
//    test keeps it.
// Rays shorter than 2 kEndGap pads are left to the near tests alone (every crossing is then
// within kNearRadius pads of an end). Every answer is still the exact test's.
// Contract (host side): it changes no answer and no count; it only proposes blockers, and
// the exact test decides (tests/embree_scene_test.cpp, tests/fast_occluders_scenes_test.cpp).
#pragma once

#include "host/host_side.h"

#include <embree3/rtcore.h>

#include <cstdint>
#include <utility>
#include <vector>

#include "host/axis_patch_test.h"
#include "host/near_patches.h"
#include "visibility/ray_patch_test.h"
#include "visibility/shooter.h"

namespace ncube {

class EmbreeScene {
 public:
  // Where Embree's part of a ray starts and ends, and how near an end a patch must be to be
  // tested exactly instead, in pads (see above).
  static constexpr double kEndGap = 0.5;
  static constexpr double kNearRadius = 2.0;

  // `candidates` (kept by reference: must outlive this scene) in their set order; `pad` is
  // the margin (scene units) of the triangles, far above the single-precision rounding of the
  // scene's coordinates.
  EmbreeScene(const std::vector<PatchCandidate>& candidates, double pad);
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  // The shooter's side of a point's rays: its M ray targets (M <= 64), its patch (the
  // position `patch`, -1: none, never blocks them) and the candidates near each target.
  // Made once per shooter, handed to every query of its rays.
  struct RayTargets {
    int patch = -1;
    std::vector<Vec3> points;
    std::vector<std::pair<int, int>> near;  // (k, position): near target k, not `patch`
    int count() const { return int(points.size()); }
  };
  RayTargets ray_targets(const Vec3* targets, int count, int shooter_position) const;

  // Bit k is set when the segment from `from` to target k crosses, by the exact test, a
  // candidate other than the positions `receiver` (-1: none) and targets.patch. Safe to
  // call from several threads at once.
  PartMask blocked(const Vec3& from, int receiver, const RayTargets& targets) const;

  // Every candidate (not excluded) the segment to target k crosses by the exact test:
  // appends (k, position) pairs to `hits`, in no particular order, possibly more than once
  // (a quadrilateral is two overlapping triangles; a patch near an end may be found by Embree
  // too).
  // Every hit along each segment is examined (no early end).
  void all_blockers(const Vec3& from, int receiver, const RayTargets& targets,
                    std::vector<std::pair<int, int>>& hits) const;

  // Sets of candidates (up to 64, `sets_of[position]`: bit s set when the candidate is in
  // set s): ray_sets[k] gets the sets holding a candidate (not excluded) the segment to
  // target k crosses by the exact test. A hit whose sets are all known already is not
  // tested, and a ray ends once it has found all of `all_sets`.
  void blocked_sets(const Vec3& from, int receiver, const RayTargets& targets,
                    const std::uint64_t* sets_of, std::uint64_t all_sets,
                    std::uint64_t* ray_sets) const;

 private:
  struct Query;
  static void exact_filter(const RTCFilterFunctionNArguments* args);
  void prepare(Query& query, const Vec3& from, int receiver, const RayTargets& targets,
               std::vector<std::pair<int, int>>* hits) const;
  // The exact test of the candidates near the rays' ends: found(k, position) for each
  // crossing of ray k.
  template <class Found>
  void near_end_crossings(const Query& query, int count, Found&& found) const;
  // The rays through Embree, but for those in `done`: returns those reported blocked.
  PartMask trace(Query& query, int count, PartMask done) const;

  const std::vector<PatchCandidate>& candidates_;
  AxisPatchTest exact_;  // segment_crosses on candidates_, fewer operations
  std::vector<int> position_of_triangle_;  // Embree's primitive -> candidate position
  double pad_;
  NearPatches near_;  // radius kNearRadius pads
  RTCScene scene_ = nullptr;
};

}  // namespace ncube

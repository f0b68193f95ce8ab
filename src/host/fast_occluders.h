// The brute-force loop's answers and counts (visibility/brute_force_occluders.h), computed
// fast on the host: Embree proposes the blockers (embree_scene.h), the exact test of
// ray_patch_test.h decides, and the loop's ray-patch tests and plane crossings are counted in
// bulk from per-plane sides of the ray targets instead of one by one. A block asked about
// before is answered from the answer cache (answer_cache.h), a block posted to the host
// threads computing ahead from there (lookahead.h).
//
// Contract (host side): it changes no answer and no count. Every mask and every counter it
// returns equals BruteForceOccluders' for the same set, policy, block and shooter, bit for bit
// (tests/occluders_test.cpp, tests/occluders_scenes_test.cpp on every scene, and whole result
// files against --reference-visibility in tests/seam_test.sh).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "host/host_side.h"
#include "host/question_key.h"
#include "host/scene_blockers.h"
#include "visibility/occluder_set.h"
#include "visibility/ray_patch_test.h"

namespace ncube {

class Lookahead;

class FastOccluders : public OccluderSet {
 public:
  // `patch_indices` are scene patch indices in the order the brute-force loop visits them;
  // a block's points are shared out over `threads` host threads (0: all cores).
  FastOccluders(const Scene& scene, std::vector<int> patch_indices, RayTestPolicy policy,
                int threads = 1);
  ~FastOccluders() override;
  FastOccluders(const FastOccluders&) = delete;
  FastOccluders& operator=(const FastOccluders&) = delete;

  // BruteForceOccluders::unblocked_parts, fast. Not to be called from two threads at once on
  // the same set (it keeps the last shooter's ray-target sides).
  void unblocked_parts(const PointBlock& block, const Shooter& shooter, PartMask* masks,
                       WorkCounts& counts) const override;
  using OccluderSet::unblocked_parts;
  const std::vector<int>& patch_indices() const override { return patch_indices_; }

  // Which side of each plane the shooter's ray targets lie on. The targets depend only on
  // the shooter's geometry and M, so the last shooter's sides are kept.
  struct TargetSides {
    ShooterKey shooter;  // whose targets these are
    int part_count = -1;
    // Per plane: its patches times the targets strictly in front of / behind it.
    std::vector<std::int64_t> in_front_tests, behind_tests;
    std::vector<PartMask> in_front, behind;  // per plane: which targets lie on each side
    std::vector<PartMask> near;              // per plane: targets within the band around it
    std::vector<int> near_planes;            // the planes with some target in their band
    EmbreeScene::RayTargets ray_targets;     // with the whole scene's patches near each
    // Over axis_order_: sums of behind_tests / in_front_tests of the first i planes.
    std::vector<std::int64_t> behind_prefix, in_front_prefix;
  };
  // The shooter's sides (not to be called from two threads at once: it keeps the last
  // shooter's, which several host threads may then share).
  std::shared_ptr<const TargetSides> target_sides(const Shooter& shooter) const;
  // The same computed afresh (safe on several threads at once).
  std::shared_ptr<const TargetSides> sides_for(const Shooter& shooter) const;

  // For host threads computing ahead (lookahead.h): the batch call's answers and counts for
  // a block, without the answer cache, on the calling thread alone and safe on several
  // threads at once. `shared` carries the block's scene-wide answers from one set asked
  // about it to the next (the sets of a group are asked about the same block).
  struct SharedBlock {
    std::shared_ptr<const SceneBlockers::SetMasks> set_masks;
    std::shared_ptr<const SceneBlockers::Lists> lists;
  };
  void answer_block_here(const PointBlock& block, const Shooter& shooter,
                         const TargetSides& sides, SharedBlock& shared, PartMask* masks,
                         WorkCounts& counts) const;
  // This set's answers in the process's answer cache (answer_cache.h), thread-safe.
  bool remembered(const Shooter& shooter, const PointBlock& block, PartMask* masks,
                  WorkCounts& counts) const;
  void remember(const Shooter& shooter, const PointBlock& block, const PartMask* masks,
                const WorkCounts& counts) const;
  // From now on the batch call first asks `lookahead` (host threads computing ahead, not
  // owned; null: none), which knows the blocks posted to it.
  void use_lookahead(Lookahead* lookahead) { lookahead_ = lookahead; }

  // Distinct planes among the set's patches (coplanar patches share one side test).
  int plane_count() const { return int(plane_size_.size()); }

 private:
  static constexpr std::size_t kMaxClasses = 32;  // planes beyond go one by one
  // The last coordinate searched in each class of axis-aligned planes and what it gave: the
  // points of a block lie on few patches, in rows, so they often share a coordinate with the
  // point before (the same coordinate gives the same sums: they depend on it alone). One per
  // host thread and TargetSides.
  struct ClassMemo {
    std::array<double, kMaxClasses> coordinate;
    std::array<std::int64_t, kMaxClasses> crossings;
    std::array<bool, kMaxClasses> known{};
  };
  // The batch call's work when the answer cache does not hold the block.
  void answer_block(const PointBlock& block, const Shooter& shooter, PartMask* masks,
                    WorkCounts& counts) const;
  // Each point's answer from the block's scene-wide answers in `shared` (as this set uses
  // them), on `threads` host threads.
  void answer_points(const PointBlock& block, const Shooter& shooter, const TargetSides& sides,
                     const SharedBlock& shared, PartMask* masks, WorkCounts& counts,
                     int threads) const;
  // The answer for one point; reads only constant data (safe on several threads). `lists`
  // and `index`: the point's blocking patches of the whole scene (null: ask Embree here).
  // `masks`: the same as bits of registered sets (this set's is set_bit_).
  PartMask answer(const Vec3& point, int receiver_patch, const Shooter& shooter,
                  const TargetSides& sides, const SceneBlockers::Lists* lists,
                  const SceneBlockers::SetMasks* masks, std::size_t index,
                  WorkCounts& counts, ClassMemo& memo) const;
  // Where this set's answers come from: the whole scene's Embree query (the whole scene,
  // testing all patches), its per-set masks (a registered share testing all patches), or
  // its lists of blockers (the first-blocker loop needs every blocker's position).
  bool uses_masks() const { return set_bit_ >= 0; }
  bool uses_lists() const {
    return !uses_masks() && (!whole_scene_ || policy_ == RayTestPolicy::kStopAtFirstBlocker);
  }
  // +1, -1 or 0 (within the tolerance) for a point and a plane (normal n, offset d).
  int side_of(double nx, double ny, double nz, double d, const Vec3& x) const {
    const double distance = nx * x.x + ny * x.y + nz * x.z - d;
    return distance > side_tolerance_ ? 1 : (distance < -side_tolerance_ ? -1 : 0);
  }
  int plane_side(int plane, const Vec3& x) const {
    return side_of(plane_x_[plane], plane_y_[plane], plane_z_[plane], plane_offset_[plane], x);
  }
  // Rays (from `point` to the targets in `rays`) that lie within the band around plane g
  // are too close to parallel for single precision to be trusted: the exact test runs on
  // every patch of the plane. Adds the blocked rays to `blocked` and, when `first` is not
  // null, lowers first[k] to the smallest blocking position.
  void in_plane_blockers(int g, const Vec3& point, PartMask rays, const Shooter& shooter,
                         int receiver_position, int shooter_position, PartMask& blocked,
                         int* first) const;
  // Plane crossings of the rays from `point` over all planes (none excluded).
  std::int64_t crossings_over_planes(const Vec3& point, const TargetSides& sides,
                                     ClassMemo& memo) const;
  // Tests and plane crossings of the first-blocker loop, given each ray's first blocker and
  // per plane the rays that cross it.
  void first_blocker_counts(const PartMask* crossing, const int* first, int part_count,
                            int receiver_position, int shooter_position, WorkCounts& counts) const;
  int position_in_set(int scene_patch) const {
    return scene_patch >= 0 && scene_patch < int(position_of_scene_patch_.size())
               ? position_of_scene_patch_[scene_patch]
               : -1;
  }

  RayTestPolicy policy_;
  int threads_;
  std::vector<int> patch_indices_;
  std::vector<PatchCandidate> patches_;  // in brute-force order (position = index)
  // The distinct planes (bit-identical normal and offset), one array per coordinate.
  std::vector<double> plane_x_, plane_y_, plane_z_, plane_offset_;
  std::vector<std::int32_t> plane_size_;  // patches in each plane
  std::vector<std::int32_t> plane_of_;    // per position
  // Axis-aligned planes (normal +-e_a up to rounding: the other components exactly 0), by
  // class (axis and exact normal component) and within a class by offset: a point's side is
  // then monotone along the class, so two binary searches per class find the planes in front
  // of and behind it. The other planes.
  std::vector<int> axis_order_;
  std::vector<int> class_begin_;       // class c is axis_order_[class_begin_[c] .. class_begin_[c+1])
  std::vector<int> class_axis_;        // its axis a
  std::vector<double> class_normal_;   // its normal's component along a
  int class_count() const { return int(class_axis_.size()); }
  std::vector<double> axis_offsets_;  // plane_offset_ of axis_order_[i] (contiguous: searched
                                      // per point and set)
  std::vector<int> other_planes_;
  std::vector<std::int32_t> plane_first_, plane_members_;  // positions of plane g's patches:
                                          // plane_members_[plane_first_[g] .. plane_first_[g+1])
  std::vector<Vec3> box_lo_, box_hi_;     // per position: bounding box grown by band_
  double side_tolerance_ = 0.0;           // distances within this count as "on the plane"
  double band_ = 0.0;                     // rays with both ends this close to a plane are
                                          // decided without Embree (docs/performance.md)
  mutable std::shared_ptr<const TargetSides> sides_;  // of the last shooter
  std::vector<int> position_of_scene_patch_;  // -1 when not in this set
  std::shared_ptr<const SceneBlockers> blockers_;
  bool whole_scene_ = false;  // every scene patch is in the set
  int set_bit_ = -1;          // this set's bit in blockers_'s registered sets, or -1
  std::uint64_t cache_id_;                // this set's answers in blockers_'s answer cache
  Lookahead* lookahead_ = nullptr;
};

}  // namespace ncube

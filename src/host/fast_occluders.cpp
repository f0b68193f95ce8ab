#include "host/fast_occluders.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>

#include "host/answer_cache.h"
#include "host/host_threads.h"
#include "host/lookahead.h"

namespace ncube {
FastOccluders::FastOccluders(const Scene& scene, std::vector<int> patch_indices,
                             RayTestPolicy policy, int threads)
    : policy_(policy),
      threads_(threads),
      patch_indices_(patch_indices),
      position_of_scene_patch_(scene.patches.size(), -1),
      cache_id_(AnswerCache::new_set_id()) {
  side_tolerance_ = plane_side_tolerance(scene);  // the brute-force loop's
  // Rays with both ends within `band_` of a plane cross it at less than band_ / scale
  // radians, too flat for single precision: the exact test alone decides them against that
  // plane's patches. Every other crossing is steep enough for Embree's padded quads
  // (scene_blockers.h, docs/performance.md).
  blockers_ = SceneBlockers::for_scene(scene);
  band_ = blockers_->band();
  patches_.reserve(patch_indices.size());
  std::map<std::array<double, 4>, int> plane_index;
  for (int scene_index : patch_indices) {
    const Patch& p = scene.patches[scene_index];
    const PatchCandidate c = make_candidate(p.polygon, p.normal, scene_index);
    position_of_scene_patch_[scene_index] = int(patches_.size());
    patches_.push_back(c);
    Vec3 lo, hi;
    grown_box(c, band_, lo, hi);
    box_lo_.push_back(lo);
    box_hi_.push_back(hi);
    const std::array<double, 4> key{c.normal.x, c.normal.y, c.normal.z, c.plane_offset};
    auto [it, added] = plane_index.emplace(key, int(plane_size_.size()));
    if (added) {
      plane_x_.push_back(c.normal.x);
      plane_y_.push_back(c.normal.y);
      plane_z_.push_back(c.normal.z);
      plane_offset_.push_back(c.plane_offset);
      plane_size_.push_back(0);
    }
    ++plane_size_[std::size_t(it->second)];
    plane_of_.push_back(it->second);
  }
  plane_first_.assign(plane_size_.size() + 1, 0);
  for (std::size_t g = 0; g < plane_size_.size(); ++g)
    plane_first_[g + 1] = plane_first_[g] + plane_size_[g];
  plane_members_.resize(patches_.size());
  std::vector<std::int32_t> next(plane_first_.begin(), plane_first_.end() - 1);
  for (int c = 0; c < size(); ++c) plane_members_[std::size_t(next[plane_of_[c]]++)] = c;
  // Classes of axis-aligned planes: one per axis and exact value of the normal's component
  // along it (the others exactly zero). A normalised axis normal is often 1 - 2^-53 or
  // 1 + 2^-52 rather than 1, so one axis may have a few classes.
  std::map<std::pair<int, double>, std::vector<int>> classes;
  for (int g = 0; g < plane_count(); ++g) {
    const double n[3] = {plane_x_[g], plane_y_[g], plane_z_[g]};
    int axis = -1;
    for (int a = 0; a < 3; ++a)
      if (std::fabs(n[a]) > 0.5 && n[(a + 1) % 3] == 0.0 && n[(a + 2) % 3] == 0.0) axis = a;
    if (axis < 0 || (classes.size() == kMaxClasses && !classes.count({axis, n[axis]}))) {
      other_planes_.push_back(g);
      continue;
    }
    classes[{axis, n[axis]}].push_back(g);
  }
  for (auto& [key, members] : classes) {
    std::sort(members.begin(), members.end(), [&](int a, int b) {
      return plane_offset_[a] < plane_offset_[b] || (plane_offset_[a] == plane_offset_[b] && a < b);
    });
    class_begin_.push_back(int(axis_order_.size()));
    class_axis_.push_back(key.first);
    class_normal_.push_back(key.second);
    axis_order_.insert(axis_order_.end(), members.begin(), members.end());
  }
  class_begin_.push_back(int(axis_order_.size()));
  for (int g : axis_order_) axis_offsets_.push_back(plane_offset_[std::size_t(g)]);
  whole_scene_ = std::count(position_of_scene_patch_.begin(), position_of_scene_patch_.end(), -1) == 0;
  if (!whole_scene_ && policy_ == RayTestPolicy::kTestAllPatches)
    set_bit_ = blockers_->register_set(patch_indices);
}

FastOccluders::~FastOccluders() {
  if (set_bit_ >= 0) blockers_->unregister_set(set_bit_);
  blockers_->answer_cache().forget_set(cache_id_);
}

std::shared_ptr<const FastOccluders::TargetSides> FastOccluders::target_sides(const Shooter& shooter) const {
  if (sides_ && sides_->shooter.is(shooter)) return sides_;
  sides_ = sides_for(shooter);
  return sides_;
}

std::shared_ptr<const FastOccluders::TargetSides> FastOccluders::sides_for(const Shooter& shooter) const {
  const int m = shooter.part_count;
  auto made = std::make_shared<TargetSides>();
  TargetSides& sides = *made;
  const std::size_t planes = plane_size_.size();
  sides.shooter = ShooterKey(shooter);
  sides.part_count = m;
  sides.in_front_tests.assign(planes, 0);
  sides.behind_tests.assign(planes, 0);
  sides.in_front.assign(planes, 0);
  sides.behind.assign(planes, 0);
  sides.near.assign(planes, 0);
  for (std::size_t g = 0; g < planes; ++g) {
    for (int k = 0; k < m; ++k) {
      const Vec3& x = shooter.targets[k];
      const int side = plane_side(int(g), x);
      if (side > 0) sides.in_front[g] |= PartMask(1) << k;
      if (side < 0) sides.behind[g] |= PartMask(1) << k;
      const double distance = plane_x_[g] * x.x + plane_y_[g] * x.y + plane_z_[g] * x.z - plane_offset_[g];
      if (std::fabs(distance) <= band_) sides.near[g] |= PartMask(1) << k;
    }
    sides.in_front_tests[g] = std::int64_t(plane_size_[g]) * __builtin_popcountll(sides.in_front[g]);
    sides.behind_tests[g] = std::int64_t(plane_size_[g]) * __builtin_popcountll(sides.behind[g]);
  }
  sides.ray_targets = blockers_->embree().ray_targets(shooter.targets.data(), m, shooter.patch);
  for (std::size_t g = 0; g < planes; ++g)
    if (sides.near[g] != 0) sides.near_planes.push_back(int(g));
  sides.behind_prefix.assign(axis_order_.size() + 1, 0);
  sides.in_front_prefix.assign(axis_order_.size() + 1, 0);
  for (std::size_t i = 0; i < axis_order_.size(); ++i) {
    sides.behind_prefix[i + 1] = sides.behind_prefix[i] + sides.behind_tests[std::size_t(axis_order_[i])];
    sides.in_front_prefix[i + 1] =
        sides.in_front_prefix[i] + sides.in_front_tests[std::size_t(axis_order_[i])];
  }
  return made;
}

void FastOccluders::in_plane_blockers(int g, const Vec3& point, PartMask rays, const Shooter& shooter,
                                  int receiver_position, int shooter_position, PartMask& blocked,
                                  int* first) const {
  // The plane's patches share its normal and offset, so the test's first half (where the ray
  // meets the plane, if it does within the segment) is the same for all of them: once per ray.
  const PatchCandidate& plane = patches_[std::size_t(plane_members_[std::size_t(plane_first_[g])])];
  for (PartMask left = rays; left != 0; left &= left - 1) {
    const int k = __builtin_ctzll(left);
    const Vec3 delta = shooter.targets[k] - point;
    Vec3 x;
    if (!segment_meets_plane(plane, point, delta, x)) continue;
    for (std::int32_t i = plane_first_[g]; i < plane_first_[g + 1]; ++i) {
      const int c = plane_members_[std::size_t(i)];
      if (c == receiver_position || c == shooter_position) continue;
      const Vec3& lo = box_lo_[std::size_t(c)];
      const Vec3& hi = box_hi_[std::size_t(c)];
      if (x.x < lo.x || x.x > hi.x || x.y < lo.y || x.y > hi.y || x.z < lo.z || x.z > hi.z)
        continue;
      if (!plane_point_inside(patches_[std::size_t(c)], x)) continue;
      blocked |= PartMask(1) << k;
      if (first && (first[k] < 0 || c < first[k])) first[k] = c;
    }
  }
}

std::int64_t FastOccluders::crossings_over_planes(const Vec3& point, const TargetSides& sides,
                                                  ClassMemo& memo) const {
  // A point in front of a plane is crossed by the rays to the targets behind it, and the
  // other way round.
  std::int64_t crossings = 0;
  for (int c = 0; c < class_count(); ++c) {
    // Along a class (offsets ascending) the point's side only falls: +1 ... 0 ... -1. For a
    // plane of class c (normal component n along axis a, the other components 0) the signed
    // distance of side_of is, bit for bit, n * coordinate - offset (the zero terms add
    // nothing but the sign of a zero, which no comparison sees), and n * coordinate is the
    // same rounded product for every plane of the class.
    const int begin = class_begin_[std::size_t(c)], end = class_begin_[std::size_t(c) + 1];
    const double coordinate = class_normal_[std::size_t(c)] * point[class_axis_[std::size_t(c)]];
    if (memo.known[std::size_t(c)] && memo.coordinate[std::size_t(c)] == coordinate) {
      crossings += memo.crossings[std::size_t(c)];
      continue;
    }
    std::int64_t in_class = 0;
    const double* offsets = axis_offsets_.data();
    const double tolerance = side_tolerance_;
    const int not_in_front = int(std::partition_point(offsets + begin, offsets + end, [&](double d) {
                               return coordinate - d > tolerance;
                             }) - offsets);
    const int behind = int(std::partition_point(offsets + not_in_front, offsets + end, [&](double d) {
                         return !(coordinate - d < -tolerance);
                       }) - offsets);
    in_class += sides.behind_prefix[std::size_t(not_in_front)] - sides.behind_prefix[std::size_t(begin)];
    in_class += sides.in_front_prefix[std::size_t(end)] - sides.in_front_prefix[std::size_t(behind)];
    memo.known[std::size_t(c)] = true;
    memo.coordinate[std::size_t(c)] = coordinate;
    memo.crossings[std::size_t(c)] = in_class;
    crossings += in_class;
  }
  for (int g : other_planes_) {
    const int side = plane_side(g, point);
    crossings += side > 0 ? sides.behind_tests[g] : (side < 0 ? sides.in_front_tests[g] : 0);
  }
  return crossings;
}

void FastOccluders::first_blocker_counts(const PartMask* crossing, const int* first, int m,
                                     int receiver_position, int shooter_position,
                                     WorkCounts& counts) const {
  // The loop of ray k tests positions 0 .. end_k - 1 (end_k: its first blocker + 1, or all
  // of them), skipping the excluded ones; it crosses the plane of position c when the point
  // and target k lie on opposite sides. Walk the positions once with the set of rays whose
  // loop is still running.
  const int n = size();
  std::array<std::pair<int, int>, kMaxShooterParts> ends;  // (end, ray), by end
  for (int k = 0; k < m; ++k) ends[k] = {first[k] < 0 ? n : first[k] + 1, k};
  std::sort(ends.begin(), ends.begin() + m);
  const bool shooter_apart = shooter_position >= 0 && shooter_position != receiver_position;
  std::uint64_t tests = 0;
  for (int k = 0; k < m; ++k) {
    const int end = ends[k].first;
    tests += std::uint64_t(end - (receiver_position >= 0 && receiver_position < end) -
                           (shooter_apart && shooter_position < end));
  }
  PartMask running = m == 64 ? ~PartMask(0) : (PartMask(1) << m) - 1;
  std::uint64_t crossings = 0;
  int next = 0;
  for (int c = 0; c < n && next < m; ++c) {
    while (next < m && ends[next].first <= c) running &= ~(PartMask(1) << ends[next++].second);
    if (c == receiver_position || c == shooter_position) continue;
    crossings += std::uint64_t(__builtin_popcountll(crossing[plane_of_[std::size_t(c)]] & running));
  }
  counts.ray_patch_tests += tests;
  counts.plane_crossings += crossings;
}

PartMask FastOccluders::answer(const Vec3& point, int receiver_patch, const Shooter& shooter,
                           const TargetSides& sides, const SceneBlockers::Lists* lists,
                           const SceneBlockers::SetMasks* masks, std::size_t index,
                           WorkCounts& counts, ClassMemo& memo) const {
  const int receiver_position = position_in_set(receiver_patch);
  const int shooter_position = position_in_set(shooter.patch);
  const int m = shooter.part_count;
  const PartMask all = shooter.all_parts();
  counts.rays += std::uint64_t(m);
  if (patches_.empty()) return all;
  const bool first_blocker = policy_ == RayTestPolicy::kStopAtFirstBlocker;
  int first[kMaxShooterParts];
  PartMask blocked = 0;
  if (masks) {
    blocked = masks->blocked[index * 64 + std::size_t(set_bit_)];
  } else if (lists) {
    // The whole scene's blockers of each ray; this set's are those it holds.
    for (int k = 0; k < m; ++k) {
      first[k] = -1;
      const std::size_t ray = index * std::size_t(m) + std::size_t(k);
      for (int i = lists->offsets[ray]; i < lists->offsets[ray + 1]; ++i) {
        const int position = position_in_set(lists->patches[std::size_t(i)]);
        if (position < 0) continue;
        blocked |= PartMask(1) << k;
        if (first[k] < 0 || position < first[k]) first[k] = position;
      }
    }
  } else {
    blocked = blockers_->embree().blocked(point, receiver_patch, sides.ray_targets);
  }
  // Rays within the band around a plane that also holds the point: decided without Embree.
  for (int g : sides.near_planes) {
    const double distance =
        plane_x_[g] * point.x + plane_y_[g] * point.y + plane_z_[g] * point.z - plane_offset_[g];
    if (!(std::fabs(distance) <= band_)) continue;
    const PartMask rays = first_blocker ? sides.near[g] : sides.near[g] & ~blocked;
    if (rays != 0)
      in_plane_blockers(g, point, rays, shooter, receiver_position, shooter_position, blocked,
                        first_blocker ? first : nullptr);
  }
  // Which rays cross each plane (the brute-force loop's plane crossings).
  const int planes = plane_count();
  std::vector<PartMask> crossing_buffer(first_blocker ? std::size_t(planes) : 0);
  std::int64_t crossings = 0;
  if (first_blocker) {
    for (int g = 0; g < planes; ++g) {
      const int side = plane_side(g, point);
      crossing_buffer[std::size_t(g)] = side > 0 ? sides.behind[g] : (side < 0 ? sides.in_front[g] : 0);
    }
  } else {
    crossings = crossings_over_planes(point, sides, memo);
  }
  if (first_blocker) {
    first_blocker_counts(crossing_buffer.data(), first, m, receiver_position, shooter_position,
                         counts);
    return all & ~blocked;
  }
  // The excluded receiver and shooter patches are no tests of the loop.
  auto crossings_of_one = [&](int position) -> std::int64_t {
    const int g = plane_of_[std::size_t(position)];
    const int side = plane_side(g, point);
    return __builtin_popcountll(side > 0 ? sides.behind[g] : (side < 0 ? sides.in_front[g] : 0));
  };
  const bool shooter_apart = shooter_position >= 0 && shooter_position != receiver_position;
  if (receiver_position >= 0) crossings -= crossings_of_one(receiver_position);
  if (shooter_apart) crossings -= crossings_of_one(shooter_position);
  const int excluded = (receiver_position >= 0) + shooter_apart;
  counts.ray_patch_tests += std::uint64_t(m) * std::uint64_t(size() - excluded);
  counts.plane_crossings += std::uint64_t(crossings);
  return all & ~blocked;
}

void FastOccluders::unblocked_parts(const PointBlock& block, const Shooter& shooter,
                                    PartMask* masks, WorkCounts& counts) const {
  // A block posted to the host threads computing ahead: computed once for the group's sets.
  if (lookahead_ && lookahead_->answers(*this, shooter, block, masks, counts)) return;
  // A block asked about before for the same shooter: the same answers and counts as then
  // (answer_cache.h; the points are compared, not assumed unchanged).
  if (remembered(shooter, block, masks, counts)) return;
  WorkCounts block_counts;
  answer_block(block, shooter, masks, block_counts);
  counts += block_counts;
  remember(shooter, block, masks, block_counts);
}

bool FastOccluders::remembered(const Shooter& shooter, const PointBlock& block, PartMask* masks,
                               WorkCounts& counts) const {
  return blockers_->answer_cache().find(cache_id_, shooter, block, masks, counts);
}

void FastOccluders::remember(const Shooter& shooter, const PointBlock& block, const PartMask* masks,
                             const WorkCounts& counts) const {
  blockers_->answer_cache().store(cache_id_, shooter, block, masks, counts);
}

void FastOccluders::answer_block(const PointBlock& block, const Shooter& shooter, PartMask* masks,
                                 WorkCounts& counts) const {
  const std::shared_ptr<const TargetSides> sides = target_sides(shooter);  // before the threads start
  SharedBlock shared;
  if (uses_masks() && !patches_.empty())
    shared.set_masks = blockers_->blocked_sets(block, shooter, threads_);
  else if (uses_lists() && !patches_.empty())
    shared.lists = blockers_->blockers(block, shooter, threads_,
                                       /*memo=*/!whole_scene_ && block.count > 1);
  answer_points(block, shooter, *sides, shared, masks, counts, threads_);
}

void FastOccluders::answer_block_here(const PointBlock& block, const Shooter& shooter,
                                      const TargetSides& sides, SharedBlock& shared,
                                      PartMask* masks, WorkCounts& counts) const {
  if (uses_masks() && !patches_.empty() && !shared.set_masks)
    shared.set_masks = blockers_->blocked_sets_here(block, shooter);
  else if (uses_lists() && !patches_.empty() && !shared.lists)
    shared.lists = blockers_->blockers(block, shooter, 1, /*memo=*/false);
  answer_points(block, shooter, sides, shared, masks, counts, 1);
}

void FastOccluders::answer_points(const PointBlock& block, const Shooter& shooter,
                                  const TargetSides& sides, const SharedBlock& shared,
                                  PartMask* masks, WorkCounts& counts, int threads) const {
  const SceneBlockers::Lists* lists = uses_lists() ? shared.lists.get() : nullptr;
  const SceneBlockers::SetMasks* set_masks = uses_masks() ? shared.set_masks.get() : nullptr;
  std::mutex merge;
  // Whole-scene answers cost an Embree query per point; the others only read memos.
  const std::size_t grain = lists || set_masks ? 64 : 8;
  parallel_chunks(threads, block.count, grain, [&](std::size_t begin, std::size_t end) {
    WorkCounts local;
    ClassMemo memo;
    for (std::size_t k = begin; k < end; ++k)
      masks[k] = answer(block.points[k], block.patches[k], shooter, sides, lists, set_masks, k,
                        local, memo);
    const std::lock_guard<std::mutex> lock(merge);
    counts += local;  // integer sums: the same whatever the order
  });
}

}  // namespace ncube

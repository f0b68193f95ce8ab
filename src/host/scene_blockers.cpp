#include "host/scene_blockers.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <mutex>
#include <tuple>

#include "host/host_threads.h"

namespace ncube {
namespace {

// Enough blocks for every group of the largest machine to have two in flight (pipelined).
constexpr std::size_t kMemoBlocks = 256;

double coordinate_scale(const Scene& scene) {
  const Bounds b = scene_bounds(scene);
  double largest = b.diagonal();
  if (b.lo.x <= b.hi.x)
    for (int axis = 0; axis < 3; ++axis)
      largest = std::max({largest, std::fabs(b.lo[axis]), std::fabs(b.hi[axis])});
  return 1.0 + largest;
}

// Identifies a scene's geometry (the address alone could be reused by another scene).
std::uint64_t fingerprint(const Scene& scene) {
  std::uint64_t h = 1469598103934665603ull;
  for (const Patch& p : scene.patches)
    for (int i = 0; i < p.polygon.count; ++i)
      for (int axis = 0; axis < 3; ++axis) {
        std::uint64_t bits;
        std::memcpy(&bits, &p.polygon[i][axis], sizeof bits);
        h = (h ^ bits) * 1099511628211ull;
      }
  return h;
}

}  // namespace

std::shared_ptr<const SceneBlockers> SceneBlockers::for_scene(const Scene& scene) {
  static std::mutex mutex;
  static std::map<std::tuple<const Scene*, std::size_t, std::uint64_t>,
                  std::weak_ptr<const SceneBlockers>>
      registry;
  const auto key = std::make_tuple(&scene, scene.patches.size(), fingerprint(scene));
  const std::lock_guard<std::mutex> lock(mutex);
  std::shared_ptr<const SceneBlockers> blockers = registry[key].lock();
  if (!blockers) {
    blockers = std::make_shared<const SceneBlockers>(scene);
    registry[key] = blockers;
  }
  return blockers;
}

SceneBlockers::SceneBlockers(const Scene& scene)
    : scale_(coordinate_scale(scene)), sets_of_patch_(scene.patches.size(), 0) {
  candidates_.reserve(scene.patches.size());
  for (int p = 0; p < int(scene.patches.size()); ++p)
    candidates_.push_back(make_candidate(scene.patches[p].polygon, scene.patches[p].normal, p));
  // Quads grow by kPad of the coordinate scale: a ray crossing a plane at more than kBand
  // radians (fast_occluders.cpp decides the others) then meets the grown quad wherever the exact
  // test finds a crossing (scene_blockers.h).
  embree_ = std::make_unique<EmbreeScene>(candidates_, kPad * scale_);
}

std::shared_ptr<const SceneBlockers::Lists> SceneBlockers::compute(const PointBlock& block,
                                                                  const Shooter& shooter,
                                                                  int threads) const {
  const std::size_t count = block.count;
  const int m = shooter.part_count;
  auto lists = std::make_shared<Lists>();
  lists->part_count = m;
  std::vector<std::vector<std::pair<int, int>>> per_point(count);
  const EmbreeScene::RayTargets targets = embree_->ray_targets(shooter.targets.data(), m, shooter.patch);
  parallel_chunks(threads, count, 16, [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k)
      embree_->all_blockers(block.points[k], block.patches[k], targets, per_point[k]);
  });
  // Grouped by ray (a patch may be listed twice for a ray: Embree meets a quad as two
  // triangles; the readers only OR and take minima, so repeats do no harm).
  lists->offsets.assign(count * std::size_t(m) + 1, 0);
  for (std::size_t k = 0; k < count; ++k)
    for (const auto& hit : per_point[k]) ++lists->offsets[k * std::size_t(m) + std::size_t(hit.first) + 1];
  for (std::size_t i = 1; i < lists->offsets.size(); ++i) lists->offsets[i] += lists->offsets[i - 1];
  lists->patches.resize(std::size_t(lists->offsets.back()));
  std::vector<int> next(lists->offsets.begin(), lists->offsets.end() - 1);
  for (std::size_t k = 0; k < count; ++k)
    for (const auto& [ray, patch] : per_point[k])
      lists->patches[std::size_t(next[k * std::size_t(m) + std::size_t(ray)]++)] = patch;
  return lists;
}

SceneBlockers::Entry* SceneBlockers::find(int kind, const PointBlock& block,
                                           const Shooter& shooter) const {
  for (auto it = memo_.begin(); it != memo_.end(); ++it) {
    const Entry& e = *it;
    // The points first: the blocks of one shot share their shooter, not their points.
    if (e.kind != kind || (kind == 1 && e.version != version_) || !e.block.is(block) ||
        !e.shooter.is(shooter))
      continue;
    if (it != memo_.begin()) {  // most recent first
      Entry moved = std::move(*it);
      memo_.erase(it);
      memo_.push_front(std::move(moved));
    }
    return &memo_.front();
  }
  return nullptr;
}

void SceneBlockers::remember(Entry entry) const {
  memo_.push_front(std::move(entry));
  if (memo_.size() > kMemoBlocks) memo_.pop_back();
}

std::shared_ptr<const SceneBlockers::Lists> SceneBlockers::blockers(const PointBlock& block,
                                                                   const Shooter& shooter,
                                                                   int threads, bool memo) const {
  if (!memo) return compute(block, shooter, threads);
  if (const Entry* e = find(0, block, shooter)) return e->lists;
  auto lists = compute(block, shooter, threads);
  remember(Entry{0, 0, ShooterKey(shooter), BlockKey(block), lists, nullptr});
  return lists;
}

int SceneBlockers::register_set(const std::vector<int>& scene_patches) const {
  if (registered_ == ~std::uint64_t(0)) return -1;
  const int bit = __builtin_ctzll(~registered_);
  registered_ |= std::uint64_t(1) << bit;
  ++version_;
  for (int p : scene_patches) sets_of_patch_[std::size_t(p)] |= std::uint64_t(1) << bit;
  return bit;
}

void SceneBlockers::unregister_set(int bit) const {
  registered_ &= ~(std::uint64_t(1) << bit);
  ++version_;
  for (std::uint64_t& sets : sets_of_patch_) sets &= ~(std::uint64_t(1) << bit);
}

std::shared_ptr<const SceneBlockers::SetMasks> SceneBlockers::blocked_sets(
    const PointBlock& block, const Shooter& shooter, int threads) const {
  if (const Entry* e = find(1, block, shooter)) return e->masks;
  auto masks = compute_sets(block, shooter, threads);
  remember(Entry{1, version_, ShooterKey(shooter), BlockKey(block), nullptr, masks});
  return masks;
}

std::shared_ptr<const SceneBlockers::SetMasks> SceneBlockers::compute_sets(
    const PointBlock& block, const Shooter& shooter, int threads) const {
  const std::size_t count = block.count;
  const int m = shooter.part_count;
  auto masks = std::make_shared<SetMasks>();
  masks->part_count = m;
  masks->blocked.assign(count * 64, 0);
  const EmbreeScene::RayTargets targets = embree_->ray_targets(shooter.targets.data(), m, shooter.patch);
  parallel_chunks(threads, count, 8, [&](std::size_t begin, std::size_t end) {
    std::uint64_t ray_sets[kMaxShooterParts];
    for (std::size_t k = begin; k < end; ++k) {
      embree_->blocked_sets(block.points[k], block.patches[k], targets, sets_of_patch_.data(),
                            registered_, ray_sets);
      PartMask* by_set = masks->blocked.data() + k * 64;
      for (int r = 0; r < m; ++r)
        for (std::uint64_t sets = ray_sets[r]; sets != 0; sets &= sets - 1)
          by_set[__builtin_ctzll(sets)] |= PartMask(1) << r;
    }
  });
  return masks;
}

}  // namespace ncube

#include "host/answer_cache.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "nodes/placement.h"
#include "host/fast_occluders.h"
#include "host/scene_blockers.h"
#include "visibility/brute_force_occluders.h"
#include "receiver_sample.h"
#include "scene/scene_loader.h"

namespace ncube {
namespace {

Scene scene1() { return load_scene(std::string(NCUBE_SOURCE_DIR) + "/scenes/scene1.json"); }
// The scene every set of these tests is built on.
const Scene& set_scene() {
  static const Scene scene = scene1();
  return scene;
}

// A shooter of `parts` targets at (k, y, z), k = 0 .. parts - 1: for the tests that need only
// keys, not a scene's geometry.
Shooter synthetic_shooter(int patch, int parts, double y, double z) {
  Shooter shooter;
  shooter.patch = patch;
  shooter.part_count = parts;
  for (int k = 0; k < parts; ++k) shooter.targets[std::size_t(k)] = Vec3(k, y, z);
  return shooter;
}

struct Block {
  std::vector<Vec3> points;
  std::vector<int> patches;
  std::vector<PartMask> masks;
  WorkCounts counts;
};

void ask(const FastOccluders& set, const Shooter& shooter, Block& block) {
  block.masks.assign(block.points.size(), 0);
  block.counts = WorkCounts{};
  set.unblocked_parts(PointBlock(block.points, block.patches), shooter, block.masks.data(),
                      block.counts);
}

// The answers of a set built afresh (a new set has a new id: nothing in the cache is its).
Block fresh(const Scene& scene, const std::vector<int>& patches, RayTestPolicy policy,
            const Shooter& shooter, Block block) {
  const FastOccluders set(scene, patches, policy);
  ask(set, shooter, block);
  return block;
}

// Per point, the literal brute-force loop over the set's patches.
Block brute_force(const FastOccluders& set, RayTestPolicy policy, const Shooter& shooter,
                  Block block) {
  const BruteForceOccluders loop(set_scene(), set.patch_indices(), policy);
  block.counts = WorkCounts{};
  for (std::size_t k = 0; k < block.points.size(); ++k)
    block.masks[k] = loop.unblocked_parts(block.points[k], block.patches[k], shooter, block.counts);
  return block;
}

TEST(AnswerCache, ABlockAskedAgainGetsTheAnswersAndCountsOfAFreshComputation) {
  const Scene scene = scene1();
  const auto blockers = SceneBlockers::for_scene(scene);  // held: the sets share it
  const AnswerCache& cache = blockers->answer_cache();
  std::mt19937 random(5);
  // A share (as on a visibility processor), the whole scene, and the first-blocker loop.
  const std::vector<int> share = visibility_share(scene, 3, 1), all = visibility_share(scene, 1, 0);
  for (const auto& [patches, policy] :
       {std::pair{share, RayTestPolicy::kTestAllPatches}, std::pair{all, RayTestPolicy::kTestAllPatches},
        std::pair{share, RayTestPolicy::kStopAtFirstBlocker}}) {
    const FastOccluders set(scene, patches, policy);
    for (int shooter_patch : {3, 40, 200}) {
      const Shooter shooter = make_shooter(scene, shooter_patch, Rgb(1.0), 64);
      const ReceiverSample sample = sample_receivers(scene, shooter_patch, 100, random);
      Block first{sample.points, sample.patches, {}, {}};
      ask(set, shooter, first);
      const std::uint64_t hits = cache.hits();
      Block again = first;
      ask(set, shooter, again);
      EXPECT_EQ(cache.hits(), hits + 1) << "the second question must be answered from memory";
      const Block reference = fresh(scene, patches, policy, shooter, first);
      EXPECT_EQ(again.masks, reference.masks);
      EXPECT_EQ(again.counts, reference.counts);
      const Block exact = brute_force(set, policy, shooter, first);
      EXPECT_EQ(again.masks, exact.masks);
      EXPECT_EQ(again.counts, exact.counts);
      // The answers must tell blocked from unblocked rays for the comparison to mean much.
      int visible = 0;
      for (PartMask m : again.masks) visible += __builtin_popcountll(m);
      EXPECT_GT(visible, 0);
      EXPECT_LT(visible, 64 * 100);
    }
  }
}

TEST(AnswerCache, ChangedPointsPatchesOrTargetsAreNotServedFromMemory) {
  const Scene scene = scene1();
  const std::vector<int> share = visibility_share(scene, 2, 0);
  const FastOccluders set(scene, share, RayTestPolicy::kTestAllPatches);
  const Shooter shooter = make_shooter(scene, 40, Rgb(1.0), 64);
  std::mt19937 random(11);
  const ReceiverSample sample = sample_receivers(scene, 40, 100, random);
  Block block{sample.points, sample.patches, {}, {}};
  ask(set, shooter, block);
  auto expect_exact = [&](const Block& changed, const Shooter& s, const char* what) {
    Block asked = changed;
    ask(set, s, asked);
    const Block exact = brute_force(set, RayTestPolicy::kTestAllPatches, s, changed);
    EXPECT_EQ(asked.masks, exact.masks) << what;
    EXPECT_EQ(asked.counts, exact.counts) << what;
  };
  // Every point moved to another element's centre (as adaptive subdivision would): same
  // count, same block position, other answers.
  Block moved = block;
  const ReceiverSample other = sample_receivers(scene, 40, 100, random);
  moved.points = other.points;
  moved.patches = other.patches;
  expect_exact(moved, shooter, "moved points");
  // One point moved by the smallest step a double allows.
  Block nudged = block;
  nudged.points[50].x = std::nextafter(nudged.points[50].x, 1e300);
  const AnswerCache& cache = SceneBlockers::for_scene(scene)->answer_cache();  // held by `set`
  const std::uint64_t misses = cache.misses();
  expect_exact(nudged, shooter, "one coordinate nudged");
  EXPECT_EQ(cache.misses(), misses + 1);
  // The same points said to lie on other patches (the receiver's patch is not tested).
  Block relabelled = block;
  for (std::size_t k = 0; k < relabelled.patches.size(); ++k)
    relabelled.patches[k] = other.patches[(k + 1) % other.patches.size()];
  expect_exact(relabelled, shooter, "other receiver patches");
  // The same shooter patch with fewer parts (other targets).
  expect_exact(block, make_shooter(scene, 40, Rgb(1.0), 16), "16 parts");
}

TEST(AnswerCache, KeepsWithinItsBudgetAndDropsTheOldestOfAShot) {
  const std::size_t budget = 64 * 1024;
  AnswerCache cache(budget);
  const Shooter shooter = synthetic_shooter(7, 4, 1, 2);
  std::vector<Vec3> points(100);
  std::vector<int> patches(100, 3);
  std::vector<PartMask> out(100);
  auto block_of = [&](int i) {
    for (int k = 0; k < 100; ++k) points[k] = Vec3(i, k, 0.5);
  };
  for (int i = 0; i < 200; ++i) {
    block_of(i);
    const std::vector<PartMask> masks(100, PartMask(i % 2 ? i : i | 0x100));  // partial masks
    WorkCounts counts;
    counts.rays = std::uint64_t(i);
    cache.store(1, shooter, PointBlock(points.data(), patches.data(), 100), masks.data(), counts);
    EXPECT_LE(cache.bytes(), budget);
  }
  EXPECT_LE(cache.peak_bytes(), budget);
  EXPECT_GT(cache.bytes(), budget / 2) << "the budget should be used, not wasted";
  // 200 blocks of about 4 KB (the points are the larger part) do not fit in 64 KB: the
  // first went, the last is there with its own answers.
  WorkCounts counts;
  block_of(0);
  EXPECT_FALSE(cache.find(1, shooter, PointBlock(points.data(), patches.data(), 100), out.data(), counts));
  block_of(199);
  ASSERT_TRUE(cache.find(1, shooter, PointBlock(points.data(), patches.data(), 100), out.data(), counts));
  EXPECT_EQ(out[0], PartMask(199));
  EXPECT_EQ(out[99], PartMask(199));
  EXPECT_EQ(counts.rays, 199u);
  // Another set is never served another's answers; a forgotten set has none left.
  EXPECT_FALSE(cache.find(2, shooter, PointBlock(points.data(), patches.data(), 100), out.data(), counts));
  cache.forget_set(1);
  EXPECT_EQ(cache.entries(), 0u);
  EXPECT_EQ(cache.bytes(), 0u) << "keys go with their last entry";
  // A budget of zero keeps nothing.
  AnswerCache off(0);
  const std::vector<PartMask> ones(100, 1);
  off.store(1, shooter, PointBlock(points.data(), patches.data(), 100), ones.data(), WorkCounts{});
  EXPECT_FALSE(off.find(1, shooter, PointBlock(points.data(), patches.data(), 100), out.data(), counts));
}


// The V shares' answers to one shooter's block are kept together: forgetting one set keeps
// the others', and the values of the same block are told apart from answers.
TEST(AnswerCache, ForgettingASetKeepsTheOtherSetsAnswersToTheSameBlock) {
  const Shooter shooter = synthetic_shooter(4, 3, 0, 1);
  std::vector<Vec3> points(40);
  std::vector<int> patches(40, 2);
  for (int k = 0; k < 40; ++k) points[std::size_t(k)] = Vec3(0.25 * k, 1, 0);
  const PointBlock block(points.data(), patches.data(), 40);
  AnswerCache cache(1 << 20);
  std::vector<PartMask> masks(40), out(40);
  for (int set = 1; set <= 3; ++set) {
    for (int k = 0; k < 40; ++k) masks[std::size_t(k)] = PartMask((k + set) % 8);
    WorkCounts counts;
    counts.ray_patch_tests = std::uint64_t(100 * set);
    counts.plane_crossings = std::uint64_t(set);
    cache.store(std::uint64_t(set), shooter, block, masks.data(), counts);
  }
  const std::vector<double> values(40, 0.125);
  cache.store_values(2, shooter, block, masks.data(), values.data());
  EXPECT_EQ(cache.entries(), 4u);
  const std::size_t before = cache.bytes();
  cache.forget_set(1);
  EXPECT_EQ(cache.entries(), 3u);
  EXPECT_LT(cache.bytes(), before);
  WorkCounts counts;
  EXPECT_FALSE(cache.find(1, shooter, block, out.data(), counts));
  ASSERT_TRUE(cache.find(3, shooter, block, out.data(), counts));
  EXPECT_EQ(counts.ray_patch_tests, 300u);
  EXPECT_EQ(counts.plane_crossings, 3u);
  EXPECT_EQ(counts.rays, 0u);
  for (int k = 0; k < 40; ++k) EXPECT_EQ(out[std::size_t(k)], PartMask((k + 3) % 8)) << k;
  std::vector<double> got(40);
  EXPECT_TRUE(cache.find_values(2, shooter, block, masks.data(), got.data()));
  EXPECT_EQ(got, values);
  EXPECT_FALSE(cache.find_values(3, shooter, block, masks.data(), got.data()));
  cache.forget_set(2);
  cache.forget_set(3);
  EXPECT_EQ(cache.entries(), 0u);
  EXPECT_EQ(cache.bytes(), 0u);
}

// Progressive refinement shoots its bright patches again and again: over budget, the answers
// of the shooter shot least often go, not those used least recently. Shooter A is shot three
// times, then B once, then C: there is room for two shots, and B's go (least recently used
// would have been A's).
TEST(AnswerCache, KeepsTheAnswersOfTheShootersShotMostOften) {
  const Shooter a = synthetic_shooter(1, 4, 1, 2), b = synthetic_shooter(2, 4, 2, 2),
                c = synthetic_shooter(3, 4, 3, 2);
  constexpr int kBlocks = 20;
  std::vector<Vec3> points(100);
  std::vector<int> patches(100, 5);
  auto block_of = [&](int i) {
    for (int k = 0; k < 100; ++k) points[k] = Vec3(i, k, 0.5);
    return PointBlock(points.data(), patches.data(), 100);
  };
  std::vector<PartMask> masks(100), out(100);
  // A shot: every block asked about, stored when not held. Returns the blocks found.
  auto shoot = [&](AnswerCache& cache, const Shooter& s) {
    int found = 0;
    for (int i = 0; i < kBlocks; ++i) {
      WorkCounts counts;
      if (cache.find(1, s, block_of(i), out.data(), counts)) {
        ++found;
        continue;
      }
      for (int k = 0; k < 100; ++k) masks[std::size_t(k)] = PartMask(k % 3 == 0 ? 0 : 15);
      counts.rays = std::uint64_t(s.patch);
      cache.store(1, s, block_of(i), masks.data(), counts);
    }
    return found;
  };
  // The bytes of the keys and of one shot's answers, measured.
  AnswerCache probe(std::size_t(1) << 30);
  shoot(probe, a);
  const std::size_t one = probe.bytes();
  shoot(probe, b);
  const std::size_t shot = probe.bytes() - one;
  AnswerCache cache(probe.bytes() + shot / 2);  // two shots fit, not three
  EXPECT_EQ(shoot(cache, a), 0);
  EXPECT_EQ(shoot(cache, a), kBlocks);
  EXPECT_EQ(shoot(cache, a), kBlocks);
  EXPECT_EQ(shoot(cache, b), 0);
  EXPECT_EQ(shoot(cache, c), 0);
  EXPECT_LE(cache.peak_bytes(), cache.budget());
  EXPECT_EQ(shoot(cache, a), kBlocks) << "the shooter shot most often keeps its answers";
  WorkCounts counts;
  EXPECT_FALSE(cache.find(1, b, block_of(0), out.data(), counts)) << "the one shot once goes";
  ASSERT_TRUE(cache.find(1, c, block_of(kBlocks - 1), out.data(), counts));
  EXPECT_EQ(counts.rays, 3u);
  EXPECT_EQ(out[0], PartMask(0));
  EXPECT_EQ(out[1], PartMask(15));
}

// Values per point (the form factors the lookahead keeps) come back only for the same set,
// shooter, block and masks, and count against the budget like answers.
TEST(AnswerCache, ValuesComeBackOnlyForTheSameMasks) {
  const Scene scene = scene1();
  const Shooter shooter = make_shooter(scene, 40, Rgb(1.0), 16);
  std::mt19937 random(3);
  const ReceiverSample sample = sample_receivers(scene, 40, 20, random);
  std::vector<PartMask> masks(20);
  std::vector<double> values(20);
  for (std::size_t k = 0; k < 20; ++k) {
    masks[k] = PartMask(k * 977);
    values[k] = 0.001 * double(k) + 1e-17;
  }
  AnswerCache cache(1 << 20);
  const std::uint64_t set = AnswerCache::new_set_id();
  cache.store_values(set, shooter, PointBlock(sample.points.data(), sample.patches.data(), 20), masks.data(),
                     values.data());
  EXPECT_GT(cache.bytes(), 20 * (sizeof(PartMask) + sizeof(double)));
  std::vector<double> got(20, -1.0);
  ASSERT_TRUE(cache.find_values(set, shooter, PointBlock(sample.points.data(), sample.patches.data(), 20),
                                masks.data(), got.data()));
  EXPECT_EQ(got, values);
  std::vector<PartMask> other = masks;
  other[19] ^= 2;
  EXPECT_FALSE(cache.find_values(set, shooter, PointBlock(sample.points.data(), sample.patches.data(), 20),
                                 other.data(), got.data()));
  EXPECT_FALSE(cache.find_values(AnswerCache::new_set_id(), shooter, PointBlock(sample.points.data(), sample.patches.data(), 20), masks.data(), got.data()));
  EXPECT_FALSE(cache.find_values(set, make_shooter(scene, 41, Rgb(1.0), 16), PointBlock(sample.points.data(), sample.patches.data(), 20), masks.data(), got.data()));
  cache.forget_set(set);
  EXPECT_EQ(cache.bytes(), 0u);
  AnswerCache none(0);
  none.store_values(set, shooter, PointBlock(sample.points.data(), sample.patches.data(), 20), masks.data(),
                    values.data());
  EXPECT_FALSE(none.find_values(set, shooter, PointBlock(sample.points.data(), sample.patches.data(), 20),
                                masks.data(), got.data()));
}

}  // namespace
}  // namespace ncube

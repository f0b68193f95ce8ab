// The host threads computing ahead (lookahead.h) hand out exactly what the node programs
// would compute themselves: each share's answers and counts equal its own batch call's (and
// the literal brute-force loop's), the form factors equal receiver_form_factor of the AND
// of the answers, whoever computed the block (a worker or the asking thread), for both
// ray-test policies, for first and repeated shots; blocks not posted, other shooters and
// other sets are not answered.
#include <gtest/gtest.h>

#include <deque>
#include <chrono>
#include <random>
#include <thread>

#include "receiver_sample.h"
#include "nodes/placement.h"
#include "host/lookahead.h"
#include "visibility/brute_force_occluders.h"
#include "radiosity/radiosity_engine.h"
#include "scene/scene_loader.h"

namespace ncube {
namespace {

constexpr int kShares = 3;
constexpr int kBlock = 10;

struct Fixture {
  explicit Fixture(RayTestPolicy policy)
      : scene(load_scene(std::string(NCUBE_SOURCE_DIR) + "/scenes/scene1.json")) {
    for (int j = 0; j < kShares; ++j) shares.emplace_back(scene, visibility_share(scene, kShares, j), policy);
    // The reference: the same shares on their own, without the lookahead.
    for (int j = 0; j < kShares; ++j)
      reference.emplace_back(scene, visibility_share(scene, kShares, j), policy);
    for (int j = 0; j < kShares; ++j)
      brute_force.emplace_back(scene, visibility_share(scene, kShares, j), policy);
  }
  Scene scene;
  std::deque<BruteForceOccluders> brute_force;  // the literal loop
  std::deque<FastOccluders> shares, reference;
};

void check_policy(RayTestPolicy policy) {
  Fixture f(policy);
  std::vector<const FastOccluders*> sets;
  for (const FastOccluders& s : f.shares) sets.push_back(&s);
  Lookahead lookahead(f.scene, sets, 1);
  for (FastOccluders& s : f.shares) s.use_lookahead(&lookahead);
  // The second round repeats the shots: answers and form factors come from the caches.
  for (int round = 0; round < 2; ++round) {
  std::mt19937 random(7);
  for (int shooter_patch : {0, 40, 150}) {
    const Shooter shooter = make_shooter(f.scene, shooter_patch, Rgb(1.0), 64);
    const ReceiverSample sample = sample_receivers(f.scene, shooter_patch, 95, random);
    const auto shot = lookahead.post(shooter, sample.points, sample.patches, kBlock);
    // Blocks asked for in turn, share by share, as the visibility processors do (the worker
    // computes some, this thread the others).
    for (std::size_t first = 0; first < sample.points.size(); first += kBlock) {
      const std::size_t n = std::min<std::size_t>(kBlock, sample.points.size() - first);
      const PointBlock block = PointBlock(sample.points, sample.patches).part(first, first + n);
      const Vec3* points = block.points;
      const int* patches = block.patches;
      std::vector<PartMask> visible(n, shooter.all_parts());
      for (int j = 0; j < kShares; ++j) {
        std::vector<PartMask> got(n), expected(n);
        WorkCounts got_counts, expected_counts, brute_counts;
        ASSERT_TRUE(lookahead.answers(f.shares[j], shooter, block, got.data(), got_counts));
        f.reference[j].unblocked_parts(block, shooter, expected.data(), expected_counts);
        EXPECT_EQ(got, expected) << "shooter " << shooter_patch << ", block at " << first << ", share " << j;
        EXPECT_EQ(got_counts, expected_counts) << "shooter " << shooter_patch << ", share " << j;
        for (std::size_t k = 0; k < n; ++k) {
          EXPECT_EQ(got[k], f.brute_force[j].unblocked_parts(points[k], patches[k], shooter,
                                                             brute_counts));
          visible[k] &= got[k];
        }
        EXPECT_EQ(got_counts, brute_counts);
        // The share's own batch call goes through the lookahead too, with the same result.
        std::vector<PartMask> again(n);
        WorkCounts again_counts;
        f.shares[j].unblocked_parts(block, shooter, again.data(), again_counts);
        EXPECT_EQ(again, expected);
        EXPECT_EQ(again_counts, expected_counts);
      }
      const double* form_factors =
          lookahead.form_factors(*shot, int(first / kBlock), visible.data(), n);
      ASSERT_NE(form_factors, nullptr);
      for (std::size_t k = 0; k < n; ++k)
        EXPECT_EQ(form_factors[k],
                  receiver_form_factor(shooter, points[k],
                                       f.scene.patches[std::size_t(patches[k])].normal, visible[k]));
      // Another visibility than the block's: no form factors.
      visible[0] ^= 1;
      EXPECT_EQ(lookahead.form_factors(*shot, int(first / kBlock), visible.data(), n), nullptr);
    }
    // Not posted: one point moved by one unit in the last place, another shooter, a set
    // that is not a share, a block cut differently.
    std::vector<Vec3> moved(sample.points.begin(), sample.points.begin() + kBlock);
    moved[3].x = std::nextafter(moved[3].x, 1e300);
    std::vector<PartMask> masks(kBlock);
    WorkCounts counts;
    EXPECT_FALSE(lookahead.answers(f.shares[0], shooter,
                                   PointBlock(moved.data(), sample.patches.data(), kBlock),
                                   masks.data(), counts));
    const Shooter other = make_shooter(f.scene, shooter_patch + 1, Rgb(1.0), 64);
    const PointBlock first_block(sample.points.data(), sample.patches.data(), kBlock);
    EXPECT_FALSE(lookahead.answers(f.shares[0], other, first_block, masks.data(), counts));
    EXPECT_FALSE(lookahead.answers(f.reference[0], shooter, first_block, masks.data(), counts));
    EXPECT_FALSE(lookahead.answers(f.shares[0], shooter,
                                   PointBlock(sample.points, sample.patches).part(1, 1 + kBlock),
                                   masks.data(), counts));
    EXPECT_EQ(counts, WorkCounts{});
  }
  }
}

TEST(Lookahead, TestingAllPatchesAnswersAsTheSharesThemselves) {
  check_policy(RayTestPolicy::kTestAllPatches);
}

TEST(Lookahead, FirstBlockerAnswersAsTheSharesThemselves) {
  check_policy(RayTestPolicy::kStopAtFirstBlocker);
}

// Guesses: given each rank's receivers and the patches' unshot power, the workers compute
// the first shot of the never-shot patch with the most power, in the blocks each rank would
// post (its receivers not on that patch, in order), into the answer cache: every share then
// remembers each such block with its own batch call's answers and counts.
TEST(Lookahead, GuessesTheNextFirstShotInTheBlocksEachRankWouldPost) {
  Fixture f(RayTestPolicy::kTestAllPatches);
  std::vector<const FastOccluders*> sets;
  for (const FastOccluders& s : f.shares) sets.push_back(&s);
  Lookahead lookahead(f.scene, sets, 1);
  constexpr int kSamples = 16;
  lookahead.guess_shots(kSamples, kBlock, 2);
  // Rank 0 holds the first 100 patches' elements, rank 1 the next 60 (in scene order).
  std::vector<Vec3> points[2];
  std::vector<int> patches[2];
  for (const Element& e : f.scene.elements)
    if (e.patch < 160) {
      points[e.patch < 100 ? 0 : 1].push_back(e.centre);
      patches[e.patch < 100 ? 0 : 1].push_back(e.patch);
    }
  lookahead.know_receivers(0, points[0], patches[0]);
  lookahead.know_receivers(1, points[1], patches[1]);
  const int guessed = 120;  // rank 1's: its own elements are no receivers
  lookahead.know_unshot({{5, 1.0}, {guessed, 3.0}, {7, 0.5}});
  const Shooter shooter = make_shooter(f.scene, guessed, Rgb(0.0), kSamples);
  for (int rank = 0; rank < 2; ++rank) {
    std::vector<Vec3> receivers;
    std::vector<int> receiver_patches;
    for (std::size_t k = 0; k < points[rank].size(); ++k)
      if (patches[rank][k] != guessed) {
        receivers.push_back(points[rank][k]);
        receiver_patches.push_back(patches[rank][k]);
      }
    for (std::size_t first = 0; first < receivers.size(); first += kBlock) {
      const std::size_t n = std::min<std::size_t>(kBlock, receivers.size() - first);
      for (int j = 0; j < kShares; ++j) {
        std::vector<PartMask> got(n), expected(n);
        WorkCounts got_counts, expected_counts;
        // The workers get there in their own time (a few seconds at most).
        bool held = false;
        for (int wait = 0; wait < 3000 && !held; ++wait) {
          held = f.shares[j].remembered(
              shooter, PointBlock(receivers, receiver_patches).part(first, first + n), got.data(),
              got_counts);
          if (!held) std::this_thread::sleep_for(std::chrono::milliseconds(10));
        }
        ASSERT_TRUE(held) << "rank " << rank << ", block at " << first << ", share " << j;
        f.reference[j].unblocked_parts(PointBlock(receivers, receiver_patches).part(first, first + n),
                                       shooter, expected.data(), expected_counts);
        EXPECT_EQ(got, expected);
        EXPECT_EQ(got_counts, expected_counts);
      }
    }
  }
}

}  // namespace
}  // namespace ncube

// EmbreeScene asks Embree only about the middle of each ray and tests the patches near its
// ends exactly (embree_scene.h): blockers crossing a ray a tenth of a pad from its start or
// its end (panel_room.h) must be found in all three query modes, as the brute-force loop
// finds them, while the receiver's and the shooter's own patches never block.
#include "host/embree_scene.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "host/scene_blockers.h"
#include "panel_room.h"

namespace ncube {
namespace {

struct PanelRoomScene {
  Scene scene = panel_room();
  std::vector<PatchCandidate> candidates;
  PanelRoomScene() {
    for (int p = 0; p < int(scene.patches.size()); ++p)
      candidates.push_back(make_candidate(scene.patches[p].polygon, scene.patches[p].normal, p));
  }
};

// The literal loop: the patches (not excluded) each ray crosses by the exact test.
unsigned brute_force_blocked(const std::vector<PatchCandidate>& candidates, const PanelRoomCase& c) {
  unsigned blocked = 0;
  for (int k = 0; k < 3; ++k)
    for (const PatchCandidate& patch : candidates)
      if (patch.scene_index != kPanelRoomFloor && patch.scene_index != kPanelRoomLight &&
          segment_crosses(patch, c.point, c.targets[std::size_t(k)] - c.point))
        blocked |= 1u << k;
  return blocked;
}

TEST(EmbreeScene, FindsBlockersWithinAFractionOfAPadOfEitherEndInEveryQueryMode) {
  const PanelRoomScene room;
  const EmbreeScene embree(room.candidates, kPanelRoomPad);
  // Sets for the set query: the standing panel alone, the hanging panel alone, the others.
  const std::uint64_t sets_of[4] = {0b100, 0b100, 0b001, 0b010};
  for (const PanelRoomCase& c : panel_room_cases()) {
    ASSERT_EQ(brute_force_blocked(room.candidates, c), c.blocked_rays);  // the worked-out case
    const EmbreeScene::RayTargets targets = embree.ray_targets(c.targets.data(), 3, kPanelRoomLight);
    EXPECT_EQ(embree.blocked(c.point, kPanelRoomFloor, targets), c.blocked_rays);

    std::vector<std::pair<int, int>> hits;
    embree.all_blockers(c.point, kPanelRoomFloor, targets, hits);
    std::sort(hits.begin(), hits.end());
    hits.erase(std::unique(hits.begin(), hits.end()), hits.end());  // repeats are allowed
    const std::vector<std::pair<int, int>> expected{{0, c.blocker}, {1, c.blocker}};
    EXPECT_EQ(hits, expected);

    std::uint64_t ray_sets[3];
    embree.blocked_sets(c.point, kPanelRoomFloor, targets, sets_of, 0b111, ray_sets);
    const std::uint64_t set = sets_of[c.blocker];
    EXPECT_EQ(ray_sets[0], set);
    EXPECT_EQ(ray_sets[1], set);
    EXPECT_EQ(ray_sets[2], 0u);
  }
}

TEST(EmbreeScene, FindsBlockersAtEveryDistanceFromTheEnds) {
  // Blockers from a hundredth of a pad to 3 pads from a ray's start (the standing panel,
  // points moved away from it along -x) or its end (the hanging panel, targets moved away
  // from it along -x), for steep, shallow and oblique rays: wherever the near tests' reach
  // ends and Embree's part of the ray begins, no crossing falls between them.
  const PanelRoomScene room;
  const EmbreeScene embree(room.candidates, kPanelRoomPad);
  int blocked_rays = 0;
  auto check = [&](const Vec3& from, const std::vector<Vec3>& targets) {
    const EmbreeScene::RayTargets ray_targets =
        embree.ray_targets(targets.data(), int(targets.size()), kPanelRoomLight);
    const PartMask blocked = embree.blocked(from, kPanelRoomFloor, ray_targets);
    for (int k = 0; k < int(targets.size()); ++k) {
      bool expected = false;
      for (const PatchCandidate& patch : room.candidates)
        if (patch.scene_index != kPanelRoomFloor && patch.scene_index != kPanelRoomLight)
          expected |= segment_crosses(patch, from, targets[std::size_t(k)] - from);
      ASSERT_TRUE(expected) << "the sweep's rays all cross a panel";
      ASSERT_EQ(bool(blocked >> k & 1), expected)
          << "from " << from.x << " " << from.y << " " << from.z << " to ray " << k;
      ++blocked_rays;
    }
  };
  std::vector<Vec3> near_end_targets;
  for (int step = 1; step <= 300; ++step) {
    const double d = 0.01 * step * kPanelRoomPad;
    check(Vec3(-d, 0, 0), {Vec3(0.6, 0, 1), Vec3(2, 0, 0.3), Vec3(1, 0.15, 0.3)});
    near_end_targets.push_back(Vec3(0.9 - d, 0, 1));
  }
  for (const Vec3& from : {Vec3(0.98, 0, 0), Vec3(3, 0, 0.95), Vec3(1.5, 0.5, 0.5)})
    for (std::size_t first = 0; first < near_end_targets.size(); first += 64)
      check(from, std::vector<Vec3>(near_end_targets.begin() + long(first),
                                    near_end_targets.begin() +
                                        long(std::min(first + 64, near_end_targets.size()))));
  EXPECT_EQ(blocked_rays, 1800);
}

TEST(EmbreeScene, FindsRaysThroughTheDiagonalOfAQuad) {
  // Embree meets a quadrilateral as two triangles sharing a diagonal of the patch grown by
  // the pad, and its fast (non-robust) triangle test may let a ray along that shared edge
  // through both. Rays aimed exactly at points of both diagonals of the grown patch, for
  // squares, long rectangles and slanted parallelograms, upright and tilted, from both
  // sides: every one must be found blocked, as the exact test finds it.
  const double pad = SceneBlockers::kPad * 10.0;
  int rays = 0;
  std::uint64_t state = 12345;
  auto uniform = [&] {  // deterministic, in [0, 1)
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return double(state >> 11) / double(1ULL << 53);
  };
  for (int shape = 0; shape < 9; ++shape) {
    const double width = shape % 3 == 0 ? 1.0 : 7.3, slant = shape % 3 == 2 ? 1.9 : 0.0;
    const double tilt = 0.35 * (shape / 3);
    const Vec3 u{std::cos(tilt), 0.0, std::sin(tilt)}, v{0.0, 1.0, 0.0};
    const Vec3 corner{0.3, -0.2, 0.1};
    const Polygon patch = Polygon::quad(corner, corner + width * u,
                                        corner + (width + slant) * u + v, corner + slant * u + v);
    const Vec3 normal = patch.normal();
    // The grown patch: each edge moved out by the pad, each corner where its edges meet.
    Vec3 grown[4];
    for (int k = 0; k < 4; ++k) {
      const Vec3 before = glm::normalize(glm::cross(patch[k] - patch[(k + 3) % 4], normal));
      const Vec3 after = glm::normalize(glm::cross(patch[(k + 1) % 4] - patch[k], normal));
      grown[k] = patch[k] + pad * (before + after) / (1.0 + glm::dot(before, after));
    }
    const std::vector<PatchCandidate> candidates{make_candidate(patch, normal, 0)};
    const EmbreeScene embree(candidates, pad);
    for (int query = 0; query < 40; ++query) {
      const Vec3 from = corner + (uniform() * 3 - 1) * width * u + (uniform() * 3 - 1) * v +
                        (query % 2 == 0 ? 1.0 : -1.0) * (0.5 + 3 * uniform()) * normal;
      std::vector<Vec3> targets;
      for (int k = 0; k < 64; ++k) {
        const Vec3 &a = grown[k % 2], &b = grown[k % 2 + 2];
        const Vec3 on_diagonal = a + (0.01 + 0.98 * uniform()) * (b - a);
        targets.push_back(on_diagonal + (0.2 + 2 * uniform()) * (on_diagonal - from));
        ASSERT_TRUE(segment_crosses(candidates[0], from, targets.back() - from));
      }
      const EmbreeScene::RayTargets ray_targets = embree.ray_targets(targets.data(), 64, -1);
      const PartMask blocked = embree.blocked(from, -1, ray_targets);
      EXPECT_EQ(blocked, ~PartMask(0)) << "shape " << shape << ", query " << query;
      rays += 64;
    }
  }
  EXPECT_EQ(rays, 9 * 40 * 64);
}

TEST(EmbreeScene, OwnPatchesDoNotBlockTheirRaysButOthersAtTheEndsDo) {
  // The same rays with nothing excluded: the floor and the light are met only at t = 0 and
  // t = 1, outside the exact test's segment, so the answers stay the same. Excluding the
  // blocking panel instead, as the receiver's patch or as the shooter's, leaves every ray
  // unblocked.
  const PanelRoomScene room;
  const EmbreeScene embree(room.candidates, kPanelRoomPad);
  for (const PanelRoomCase& c : panel_room_cases()) {
    EXPECT_EQ(embree.blocked(c.point, -1, embree.ray_targets(c.targets.data(), 3, -1)),
              c.blocked_rays);
    EXPECT_EQ(embree.blocked(c.point, c.blocker, embree.ray_targets(c.targets.data(), 3, -1)), 0u);
    const int other = c.blocker == kPanelRoomStanding ? kPanelRoomHanging : kPanelRoomStanding;
    EXPECT_EQ(embree.blocked(c.point, other, embree.ray_targets(c.targets.data(), 3, c.blocker)), 0u);
  }
}

}  // namespace
}  // namespace ncube

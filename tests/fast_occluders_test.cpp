#include "host/fast_occluders.h"
#include "visibility/brute_force_occluders.h"

#include <gtest/gtest.h>
#include <cmath>
#include <random>

#include "panel_room.h"

namespace ncube {
namespace {

// A random scene of small quads and triangles scattered in a unit cube, some coplanar and
// axis-aligned (as in real rooms), some at random orientations.
Scene random_scene(unsigned seed, int patches) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0), size(0.02, 0.25);
  Scene scene;
  scene.name = "random";
  for (int i = 0; i < patches; ++i) {
    const Vec3 o(unit(rng), unit(rng), unit(rng));
    Vec3 u, v;
    if (i % 3 == 0) {  // axis aligned
      const int axis = i % 9 / 3;
      u = Vec3(0.0);
      v = Vec3(0.0);
      u[(axis + 1) % 3] = size(rng);
      v[(axis + 2) % 3] = size(rng);
    } else {
      u = Vec3(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5) * 0.4;
      v = Vec3(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5) * 0.4;
    }
    Patch p;
    p.polygon = i % 4 == 1 ? Polygon::triangle(o, o + u, o + v) : Polygon::quad(o, o + u, o + u + v, o + v);
    p.reflectance = Rgb(0.5);
    p.nu = 2;
    p.nv = 2;
    scene.patches.push_back(p);
  }
  scene.build_elements();
  return scene;
}

void expect_same_as_brute_force(RayTestPolicy policy, unsigned seed) {
  const Scene scene = random_scene(seed, 300);
  std::vector<int> all(scene.patches.size());
  for (int i = 0; i < int(all.size()); ++i) all[i] = i;
  // One full set and one share of every third patch (as on a visibility processor).
  std::vector<int> share;
  for (int i = 1; i < int(all.size()); i += 3) share.push_back(i);
  for (const auto& set : {all, share}) {
    const FastOccluders occluders(scene, set, policy);
    const BruteForceOccluders brute_force(scene, set, policy);
    int blocked_rays = 0, visible_rays = 0;
    std::uint64_t tests = 0, crossings = 0;
    for (int shooter_patch = 0; shooter_patch < 12; ++shooter_patch) {
      const Shooter shooter = make_shooter(scene, shooter_patch, Rgb(1.0), 16);
      for (int e = 0; e < int(scene.elements.size()); e += 7) {
        const Element& element = scene.elements[e];
        if (element.patch == shooter_patch) continue;
        WorkCounts fast, slow;
        const PartMask a = occluders.unblocked_parts(element.centre, element.patch, shooter, fast);
        const PartMask b =
            brute_force.unblocked_parts(element.centre, element.patch, shooter, slow);
        ASSERT_EQ(a, b) << "element " << e << " shooter " << shooter_patch;
        ASSERT_EQ(fast, slow) << "element " << e << " shooter " << shooter_patch;
        tests += slow.ray_patch_tests;
        crossings += slow.plane_crossings;
        const int visible = __builtin_popcountll(a);
        visible_rays += visible;
        blocked_rays += 16 - visible;
      }
    }
    // The random scene must exercise both outcomes, or the comparison proves little.
    EXPECT_GT(blocked_rays, 1000);
    EXPECT_GT(visible_rays, 1000);
    // Plane crossings must be neither none nor all of the tests for their count to be tested.
    EXPECT_GT(crossings, tests / 20);
    EXPECT_LT(crossings, tests);
  }
}

TEST(FastOccluders, HostAnswersGiveBruteForceAnswersAndCountsWhenTestingAllPatches) {
  for (unsigned seed : {1u, 2u, 3u}) expect_same_as_brute_force(RayTestPolicy::kTestAllPatches, seed);
}

TEST(FastOccluders, HostAnswersGiveBruteForceAnswersAndCountsWhenStoppingAtFirstBlocker) {
  for (unsigned seed : {4u, 5u, 6u})
    expect_same_as_brute_force(RayTestPolicy::kStopAtFirstBlocker, seed);
}

TEST(FastOccluders, EachRayIsTestedAgainstAllOtherPatches) {
  const Scene scene = random_scene(7, 50);
  std::vector<int> all(50);
  for (int i = 0; i < 50; ++i) all[i] = i;
  const FastOccluders occluders(scene, all, RayTestPolicy::kTestAllPatches);
    const BruteForceOccluders brute_force(scene, all, RayTestPolicy::kTestAllPatches);
  const Shooter shooter = make_shooter(scene, 3, Rgb(1.0), 64);
  WorkCounts counts;
  occluders.unblocked_parts(scene.elements[0].centre, 0, shooter, counts);
  EXPECT_EQ(counts.rays, 64u);
  EXPECT_EQ(counts.ray_patch_tests, 64u * 48u);  // all patches but receiver and shooter
}

// One square wall, x = 0 and |y|, |z| <= 1.
Scene wall_scene() {
  Scene scene;
  Patch wall;
  wall.polygon = Polygon::quad({0, -1, -1}, {0, 1, -1}, {0, 1, 1}, {0, -1, 1});
  wall.reflectance = Rgb(0.5);
  scene.patches = {wall};
  scene.build_elements();
  return scene;
}

TEST(FastOccluders, SegmentTestFindsACrossingSquareAndIgnoresTheEndpoints) {
  const Scene scene = wall_scene();
  const FastOccluders occluders(scene, {0}, RayTestPolicy::kTestAllPatches);
    const BruteForceOccluders brute_force(scene, {0}, RayTestPolicy::kTestAllPatches);
  Shooter shooter;
  shooter.patch = -1;
  shooter.part_count = 2;
  shooter.targets[0] = Vec3(1, 0, 0);    // through the wall
  shooter.targets[1] = Vec3(-1, 0, 3);   // passes above it
  WorkCounts counts;
  EXPECT_EQ(occluders.unblocked_parts(Vec3(-1, 0, 0), -1, shooter, counts), PartMask(2));
}

TEST(FastOccluders, CountsARayAsAPlaneCrossingWhenItsEndsLieOnOppositeSides) {
  // The wall x = 0, |y|, |z| <= 1. From (-1, 0, 0): the first ray goes through the wall, the
  // second stays on its side, the third crosses its plane beside it (no hit, but the loop
  // still computes the hit point and tests the edges), the fourth ends in the plane.
  const Scene scene = wall_scene();
  Shooter shooter;
  shooter.patch = -1;
  shooter.part_count = 4;
  shooter.targets[0] = Vec3(1, 0, 0);
  shooter.targets[1] = Vec3(-1, 0, 3);
  shooter.targets[2] = Vec3(1, 0, 5);
  shooter.targets[3] = Vec3(0, 0, 5);
  for (RayTestPolicy policy : {RayTestPolicy::kTestAllPatches, RayTestPolicy::kStopAtFirstBlocker}) {
    const FastOccluders occluders(scene, {0}, policy);
    const BruteForceOccluders brute_force(scene, {0}, policy);
    WorkCounts counts, reference;
    EXPECT_EQ(occluders.unblocked_parts(Vec3(-1, 0, 0), -1, shooter, counts), PartMask(0b1110));
    brute_force.unblocked_parts(Vec3(-1, 0, 0), -1, shooter, reference);
    EXPECT_EQ(counts.ray_patch_tests, 4u);
    EXPECT_EQ(counts.plane_crossings, 2u);
    EXPECT_EQ(counts, reference);
  }
}

TEST(FastOccluders, FindBlockersNearTheRaysEndsForTheWholeSceneAndShares) {
  // panel_room.h: blockers a tenth of a pad from a ray's start or end, which Embree is not
  // asked about: the whole scene (one Embree query, or lists for the first-blocker loop)
  // and a share holding the panels (a registered set's bits, or lists) all find them.
  const Scene scene = panel_room();
  const std::vector<int> all{0, 1, 2, 3}, panels{kPanelRoomStanding, kPanelRoomHanging};
  for (RayTestPolicy policy : {RayTestPolicy::kTestAllPatches, RayTestPolicy::kStopAtFirstBlocker})
    for (const auto& set : {all, panels}) {
      const FastOccluders occluders(scene, set, policy);
    const BruteForceOccluders brute_force(scene, set, policy);
      for (const PanelRoomCase& c : panel_room_cases()) {
        Shooter shooter;
        shooter.patch = kPanelRoomLight;
        shooter.part_count = 3;
        std::copy(c.targets.begin(), c.targets.end(), shooter.targets.begin());
        WorkCounts counts, reference;
        const PartMask visible = PartMask(0b111 & ~c.blocked_rays);
        EXPECT_EQ(occluders.unblocked_parts(c.point, kPanelRoomFloor, shooter, counts), visible);
        EXPECT_EQ(brute_force.unblocked_parts(c.point, kPanelRoomFloor, shooter, reference),
                  visible);
        EXPECT_EQ(counts, reference);
      }
    }
}

// The loader's normal of an axis-aligned rectangle is +-1 only up to rounding (normalised
// cross product), and the fast count sorts such planes into classes by that exact value. At
// points whose distance to the plane lies at the side tolerance, n * z and +-z round apart:
// the crossings counted there must still be the brute-force loop's.
TEST(FastOccluders, CountsCrossingsAtTheToleranceOfPlanesWhoseNormalIsNotExactlyOne) {
  Scene scene;
  scene.name = "near-one normals";
  // Floors of different sizes at different heights until one normal's z is not exactly 1.
  double nz = 1.0;
  int plane = -1;
  for (int i = 0; i < 40 && nz == 1.0; ++i) {
    const double w = 0.1 + 0.013 * i, h = 0.07 + 0.029 * i, z = 0.05 + 0.021 * i;
    Patch p;
    p.polygon = Polygon::quad(Vec3(0, 0, z), Vec3(w, 0, z), Vec3(w, h, z), Vec3(0, h, z));
    p.reflectance = Rgb(0.5);
    p.nu = 1;
    p.nv = 1;
    scene.patches.push_back(p);
    scene.build_elements();
    nz = scene.patches.back().normal.z;
    plane = int(scene.patches.size()) - 1;  // the one with that normal, when it is not 1
  }
  ASSERT_NE(nz, 1.0);
  Patch light;  // below everything, facing up: a point above a plane is crossed by its rays
  light.polygon = Polygon::quad(Vec3(0, 0, -1), Vec3(1, 0, -1), Vec3(1, 1, -1), Vec3(0, 1, -1));
  light.reflectance = Rgb(0.5);
  light.emission = Rgb(1.0);
  light.nu = 1;
  light.nv = 1;
  scene.patches.push_back(light);
  scene.build_elements();
  const int shooter_patch = int(scene.patches.size()) - 1;
  std::vector<int> all(scene.patches.size());
  for (int i = 0; i < int(all.size()); ++i) all[i] = i;
  const FastOccluders fast(scene, all, RayTestPolicy::kTestAllPatches);
  const BruteForceOccluders brute_force(scene, all, RayTestPolicy::kTestAllPatches);
  const Shooter shooter = make_shooter(scene, shooter_patch, Rgb(1.0), 16);
  // Points whose height walks double by double across plane + tolerance and plane - tolerance.
  const Patch& p = scene.patches[std::size_t(plane)];
  const double offset = glm::dot(p.normal, p.polygon[0]);
  const double tolerance = plane_side_tolerance(scene);
  int rounding_apart = 0;
  for (double edge : {offset + tolerance, offset - tolerance}) {
    double z = edge / nz;
    for (int s = 0; s < 40; ++s) z = std::nextafter(z, -1.0);
    for (int step = 0; step < 80; ++step, z = std::nextafter(z, 2.0)) {
      const double by_normal = nz * z - offset, by_one = z - offset;
      rounding_apart += (by_normal > tolerance) != (by_one > tolerance) ||
                        (by_normal < -tolerance) != (by_one < -tolerance);
      const Vec3 point(0.5, 0.5, z);
      WorkCounts a, b;
      ASSERT_EQ(fast.unblocked_parts(point, -1, shooter, a),
                brute_force.unblocked_parts(point, -1, shooter, b));
      ASSERT_EQ(a, b) << "height " << z;
    }
  }
  // The walk must reach heights where taking the normal as exactly 1 would count otherwise.
  EXPECT_GT(rounding_apart, 0);
}

}  // namespace
}  // namespace ncube

// ThreadedAssist (host/threaded_assist.h) remembers a radiosity processor's receivers' form
// factors across shots in the answer cache, and hands them back only for exactly the same
// question: the same shooter, the same receivers (points and patches) and the same
// visibility masks, compared in full. Checked against receiver_form_factor itself and
// against whole progressive runs with no host help at all (a repeated shot is then served
// from memory and the radiosities stay equal bit for bit).
#include "host/threaded_assist.h"

#include <gtest/gtest.h>

#include <cstring>
#include <numeric>
#include <set>

#include "host/answer_cache.h"
#include "host/fast_occluders.h"
#include "radiosity/radiosity_engine.h"
#include "scene/scene_loader.h"

namespace ncube {
namespace {

Scene load(const char* name) {
  return load_scene(std::string(NCUBE_SOURCE_DIR) + "/scenes/" + name);
}

std::vector<int> every_patch(const Scene& scene) {
  std::vector<int> all(scene.patches.size());
  std::iota(all.begin(), all.end(), 0);
  return all;
}

// A few receivers of `scene` (element centres and their patches) and their form factors
// from receiver_form_factor for `shooter` and `masks`.
struct Receivers {
  std::vector<Vec3> points;
  std::vector<int> patches;
  std::vector<PartMask> masks;
  PointBlock block() const { return PointBlock(points, patches); }
  std::vector<double> form_factors(const Scene& scene, const Shooter& shooter) const {
    std::vector<double> values(points.size());
    for (std::size_t k = 0; k < points.size(); ++k)
      values[k] = receiver_form_factor(shooter, points[k],
                                       scene.patches[std::size_t(patches[k])].normal, masks[k]);
    return values;
  }
};

Receivers some_receivers(const Scene& scene, int shooter_patch, const Shooter& shooter) {
  Receivers r;
  for (std::size_t e = 0; e < scene.elements.size() && r.points.size() < 40; e += 7) {
    if (scene.elements[e].patch == shooter_patch) continue;
    r.points.push_back(scene.elements[e].centre);
    r.patches.push_back(scene.elements[e].patch);
    // Every part, none, and partial masks in turn.
    const std::size_t k = r.points.size();
    r.masks.push_back(
        k % 3 == 0
            ? shooter.all_parts()
            : (k % 3 == 1 ? PartMask(0) : PartMask(0x5a5a5a5a5a5a5a5aull) & shooter.all_parts()));
  }
  return r;
}

TEST(ThreadedAssist, HandsBackTheFormFactorsOfExactlyTheSameQuestion) {
  const Scene scene = load("scene1.json");
  auto blockers = SceneBlockers::for_scene(scene);
  ThreadedAssist assist(1, blockers);
  const int shooter_patch = scene.elements.front().patch;
  const Shooter shooter = make_shooter(scene, shooter_patch, Rgb(1.0), 64);
  Receivers r = some_receivers(scene, shooter_patch, shooter);
  const std::vector<double> expected = r.form_factors(scene, shooter);
  std::vector<double> out(r.points.size(), -1.0);

  EXPECT_FALSE(assist.remembered_form_factors(shooter, r.block(), r.masks.data(), out.data()));
  assist.remember_form_factors(shooter, r.block(), r.masks.data(), expected.data());
  ASSERT_TRUE(assist.remembered_form_factors(shooter, r.block(), r.masks.data(), out.data()));
  for (std::size_t k = 0; k < out.size(); ++k)
    EXPECT_EQ(std::memcmp(&out[k], &expected[k], sizeof(double)), 0) << k;

  // Another visibility of one receiver: not the same question.
  Receivers other_mask = r;
  other_mask.masks[2] ^= 1;
  EXPECT_FALSE(assist.remembered_form_factors(shooter, other_mask.block(), other_mask.masks.data(),
                                              out.data()));
  // One receiver moved by one unit in the last place.
  Receivers moved = r;
  moved.points[5].y = std::nextafter(moved.points[5].y, 1e300);
  EXPECT_FALSE(
      assist.remembered_form_factors(shooter, moved.block(), moved.masks.data(), out.data()));
  // Another shooter, and the same shooter with fewer parts.
  const int other_patch = shooter_patch + 1 == int(scene.patches.size()) ? 0 : shooter_patch + 1;
  EXPECT_FALSE(assist.remembered_form_factors(make_shooter(scene, other_patch, Rgb(1.0), 64),
                                              r.block(), r.masks.data(), out.data()));
  EXPECT_FALSE(assist.remembered_form_factors(make_shooter(scene, shooter_patch, Rgb(1.0), 16),
                                              r.block(), r.masks.data(), out.data()));
  // Without a cache nothing is remembered.
  ThreadedAssist forgetful(1, nullptr);
  forgetful.remember_form_factors(shooter, r.block(), r.masks.data(), expected.data());
  EXPECT_FALSE(forgetful.remembered_form_factors(shooter, r.block(), r.masks.data(), out.data()));
}

TEST(ThreadedAssist, RepeatedShotsTakeRememberedFormFactorsAndRadiositiesStayEqual) {
  const Scene scene = load("scene0.json");
  const std::vector<int> all = every_patch(scene);
  ProgressiveOptions options;
  options.samples = 16;
  options.max_iterations = 120;

  // No host help: every form factor computed by the engine itself.
  RadiosityEngine plain(scene, all);
  const FastOccluders plain_occluders(scene, all, options.ray_policy, 1);
  const ProgressiveRun plain_run = run_progressive(plain, plain_occluders, options);
  const std::set<int> distinct(plain_run.shooters.begin(), plain_run.shooters.end());
  ASSERT_LT(distinct.size(), plain_run.shooters.size()) << "the run must repeat a shooter";

  auto blockers = SceneBlockers::for_scene(scene);
  RadiosityEngine helped(scene, all);
  ThreadedAssist assist(2, blockers);
  helped.use_host_assist(&assist, 0);
  const FastOccluders occluders(scene, all, options.ray_policy, 1);
  const std::uint64_t hits_before = blockers->answer_cache().hits();
  const ProgressiveRun run = run_progressive(helped, occluders, options);
  // The answers of a repeated shot and its form factors both come from the cache: more hits
  // than the answers alone would give.
  EXPECT_GT(blockers->answer_cache().hits() - hits_before,
            plain_run.shooters.size() - distinct.size());

  EXPECT_EQ(run.shooters, plain_run.shooters);
  for (std::size_t e = 0; e < scene.elements.size(); ++e) {
    const Rgb a = helped.element_radiosity(int(e)), b = plain.element_radiosity(int(e));
    EXPECT_EQ(std::memcmp(&a, &b, sizeof(Rgb)), 0) << "element " << e;
  }
}

}  // namespace
}  // namespace ncube

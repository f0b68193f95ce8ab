// The visibility processors' work (section 3) in a scene small enough to count by hand: each
// one is charged the ray-patch tests and plane crossings of its own share of the patches, so
// a share that the rays cross costs more than one they pass by. Each TEST runs its own
// SimGrid Engine, hence its own process under ctest.
#include <gtest/gtest.h>

#include "machine/cost_model.h"
#include "machine/platform_config.h"
#include "simulation/simulation.h"

namespace ncube {
namespace {

std::string repo(const std::string& path) { return std::string(NCUBE_SOURCE_DIR) + "/" + path; }

// One element per patch; the normal is u x v.
Patch rectangle(const Vec3& origin, const Vec3& u, const Vec3& v, double emission) {
  Patch p;
  p.polygon = Polygon::quad(origin, origin + u, origin + u + v, origin + v);
  p.reflectance = Rgb(0.5);
  p.emission = Rgb(emission);
  return p;
}

// Patch 0: a table top at y = 1 over x in [2, 3]. Patch 1: the light at y = 2 over
// x, z in [0, 1], facing down. Patch 2: a wall at x = 5 facing -x, y in [0, 1.6]. Patch 3: the
// floor under the light. With V = 2, visibility processor 0 stores patches 0 and 1 and
// processor 1 patches 2 and 3 (consecutive runs).
Scene table_light_wall_floor() {
  const Vec3 X(1, 0, 0), Y(0, 1, 0), Z(0, 0, 1);
  Scene s;
  s.name = "table-light-wall-floor";
  s.patches = {rectangle({2, 1, 0}, Z, X, 0.0), rectangle({0, 2, 0}, X, Z, 1.0),
               rectangle({5, 0, 0}, Z, 1.6 * Y, 0.0), rectangle({0, 0, 0}, Z, X, 0.0)};
  s.build_elements();
  return s;
}

TEST(VisibilityProcessor, IsChargedTheTestsAndPlaneCrossingsOfItsShare) {
  const Scene scene = table_light_wall_floor();
  SimulationConfig config;
  config.radiosity_processors = 1;
  config.visibility_processors = 2;
  config.options.samples = 4;  // targets at x, z in {0.25, 0.75}, y = 2
  config.options.max_iterations = 1;  // the light shoots
  const PlatformConfig platform = load_platform_config(repo("platforms/ncube2.json"));
  const CostModel costs = load_cost_model(repo("platforms/cost_model.json"));
  const SimulationResult result = run_simulation(scene, config, platform, costs);
  ASSERT_EQ(result.status, RunStatus::kOk);
  ASSERT_EQ(result.shooters, std::vector<int>({1}));
  ASSERT_EQ(result.nodes.size(), 3u);

  // Points: the table's (2.5, 1, 0.5), the wall's (5, 0.8, 0.5), the floor's (0.5, 0, 0.5);
  // 4 rays each. Processor 0 tests the table for the wall and floor points (the light is the
  // shooter, the table the first point's own patch): 8 tests, and all 8 rays rise from below
  // the table's plane to the light above it. Processor 1 tests the wall and the floor for the
  // table point, the floor for the wall point, the wall for the floor point: 16 tests, none
  // crossing (every point and target lies in front of the wall's plane x = 5 and above the
  // floor's).
  const WorkCounts& crossed = result.nodes[1].counts;
  const WorkCounts& passed = result.nodes[2].counts;
  EXPECT_EQ(crossed.rays, 12u);
  EXPECT_EQ(crossed.ray_patch_tests, 8u);
  EXPECT_EQ(crossed.plane_crossings, 8u);
  EXPECT_EQ(passed.rays, 12u);
  EXPECT_EQ(passed.ray_patch_tests, 16u);
  EXPECT_EQ(passed.plane_crossings, 0u);

  auto seconds = [&](double rays, double tests, double crossings) {
    return (costs.flops_per_ray * rays + costs.flops_per_ray_patch_test * tests +
            costs.flops_per_plane_crossing * crossings) / platform.node_speed;
  };
  EXPECT_NEAR(result.nodes[1].compute_seconds, seconds(12, 8, 8), 1e-12);
  EXPECT_NEAR(result.nodes[2].compute_seconds, seconds(12, 16, 0), 1e-12);
}

}  // namespace
}  // namespace ncube

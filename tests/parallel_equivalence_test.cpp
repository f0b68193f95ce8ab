// The parallel solution is the sequential one (issue: "the parallel solution is the
// sequential one"): for every configuration the shooters and every patch's radiosity after
// k iterations equal those of the host's sequential solver. The parallel programs perform
// the same floating-point operations on each element in the same order, so they agree to
// the last bit; the stated tolerance is 1e-12 relative. Each TEST runs its own SimGrid
// Engine, hence its own process under ctest.
#include <gtest/gtest.h>

#include "host/fast_occluders.h"
#include <numeric>

#include "machine/cost_model.h"
#include "machine/platform_config.h"
#include "scene/scene_loader.h"
#include "simulation/simulation.h"

namespace ncube {
namespace {

std::string repo(const std::string& path) { return std::string(NCUBE_SOURCE_DIR) + "/" + path; }

void expect_same_as_sequential(const std::string& scene_name, int R, int V, int iterations,
                               bool pipelined = false, int block_size = 100,
                               bool subdivide = false, bool balance = false) {
  const Scene scene = load_scene(repo("scenes/" + scene_name));
  ProgressiveOptions options;
  options.samples = 16;  // M = 16 (the paper's smaller M), as when it was the default
  options.max_iterations = iterations;
  options.subdivision.enabled = subdivide;

  std::vector<int> all(scene.patches.size());
  std::iota(all.begin(), all.end(), 0);
  RadiosityEngine reference(scene, all);
  const FastOccluders occluders(scene, all, options.ray_policy);
  const ProgressiveRun sequential = run_progressive(reference, occluders, options);

  SimulationConfig config;
  config.radiosity_processors = R;
  config.visibility_processors = V;
  config.options = options;
  config.pipelined = pipelined;
  config.block_size = block_size;
  config.balancing.enabled = balance;
  config.memory_cap = !subdivide;  // the sequential solver has no memory limit
  const SimulationResult parallel =
      run_simulation(scene, config, load_platform_config(repo("platforms/ncube2.json")),
                     load_cost_model(repo("platforms/cost_model.json")));
  ASSERT_EQ(parallel.status, RunStatus::kOk);
  EXPECT_EQ(parallel.iterations, iterations);
  EXPECT_EQ(parallel.shooters, sequential.shooters);
  ASSERT_EQ(parallel.iteration_seconds.size(), std::size_t(iterations));
  for (int p = 0; p < int(scene.patches.size()); ++p) {
    const Rgb expected = reference.patch_radiosity(p);
    for (int c = 0; c < 3; ++c)
      ASSERT_NEAR(parallel.patch_radiosity[p][c], expected[c], 1e-12 * (1.0 + expected[c]))
          << "patch " << p;
  }
  // Section 4.1: the same elements, cut the same way, with the same radiosities.
  for (int p = 0; p < int(scene.patches.size()); ++p) {
    const StoredPatch& expected = reference.store().patches()[std::size_t(p)];
    const PatchSolution& got = parallel.solution[std::size_t(p)];
    ASSERT_EQ(got.cells.size(), expected.elements.size()) << "patch " << p;
    for (std::size_t k = 0; k < got.cells.size(); ++k) {
      ASSERT_EQ(got.cells[k], expected.elements[k].cell);
      ASSERT_EQ(got.radiosity[k], expected.elements[k].radiosity);
    }
  }
  if (subdivide) {
    EXPECT_GT(sequential.elements.back(), scene.element_total()) << "nothing was cut";
  }
  if (balance) {
    EXPECT_GT(parallel.patches_moved, 0) << "balancing moved nothing: the test shows nothing";
  }
}

TEST(ParallelEquivalence, Scene0R4V0) { expect_same_as_sequential("scene0.json", 4, 0, 25); }
TEST(ParallelEquivalence, Scene0R8V7) { expect_same_as_sequential("scene0.json", 8, 7, 25); }
TEST(ParallelEquivalence, Scene0R5V11NotAPowerOfTwo) {
  expect_same_as_sequential("scene0.json", 5, 11, 25);
}
TEST(ParallelEquivalence, Scene0R3V2PipelinedSmallBlocks) {
  expect_same_as_sequential("scene0.json", 3, 2, 25, true, 7);
}
TEST(ParallelEquivalence, Scene0R52V0OnePatchEach) {
  expect_same_as_sequential("scene0.json", 52, 0, 25);
}
TEST(ParallelEquivalence, Scene1R4V3) { expect_same_as_sequential("scene1.json", 4, 3, 4); }

// Sections 4.1 and 4.2: with adaptive subdivision the radiosity processors cut their
// elements exactly as the sequential solver does, and moving patches changes nothing.
TEST(ParallelEquivalence, SubdivisionCornellBoxR4V3) {
  expect_same_as_sequential("cornell-box.json", 4, 3, 15, false, 100, true);
}
TEST(ParallelEquivalence, SubdivisionScene1R8V0Balanced) {
  expect_same_as_sequential("scene1.json", 8, 0, 12, false, 100, true, true);
}
TEST(ParallelEquivalence, SubdivisionScene1R4V1PipelinedBalanced) {
  expect_same_as_sequential("scene1.json", 4, 1, 6, true, 37, true, true);
}

}  // namespace
}  // namespace ncube

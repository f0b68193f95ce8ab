// Host speed of the radiosity engine (a reported figure, not a test): host seconds per
// progressive-refinement iteration and shadow rays per second, with exact brute-force counts.
// Run: build/benchmarks [--benchmark_filter=scene3]
#include <benchmark/benchmark.h>

#include <numeric>
#include <string>

#include "radiosity/radiosity_engine.h"
#include "scene/scene_loader.h"

namespace {

void iteration(benchmark::State& state, const std::string& scene_name) {
  const ncube::Scene scene =
      ncube::load_scene(std::string(NCUBE_SOURCE_DIR) + "/scenes/" + scene_name + ".json");
  std::vector<int> all(scene.patches.size());
  std::iota(all.begin(), all.end(), 0);
  ncube::RadiosityEngine engine(scene, all);
  const ncube::Occluders occluders(scene, all, ncube::RayTestPolicy::kTestAllPatches);
  ncube::ProgressiveOptions options;
  options.max_iterations = 1;
  std::uint64_t rays = 0, tests = 0;
  for (auto _ : state) {
    // One iteration each time: the brightest remaining patch shoots.
    const ncube::ProgressiveRun run = ncube::run_progressive(engine, occluders, options);
    rays += run.total.rays;
    tests += run.total.ray_patch_tests;
  }
  state.counters["rays_per_second"] = benchmark::Counter(double(rays), benchmark::Counter::kIsRate);
  state.counters["rays_per_iteration"] =
      benchmark::Counter(double(rays), benchmark::Counter::kAvgIterations);
  state.counters["brute_force_tests_per_iteration"] =
      benchmark::Counter(double(tests), benchmark::Counter::kAvgIterations);
}

BENCHMARK_CAPTURE(iteration, scene1, std::string("scene1"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(iteration, scene2, std::string("scene2"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(iteration, scene3, std::string("scene3"))
    ->Unit(benchmark::kMillisecond)
    ->MinTime(5.0)
    ->UseRealTime();

}  // namespace

// Host speed of the radiosity engine (a reported figure, not a test): host seconds per
// progressive-refinement iteration and shadow rays per second, with exact brute-force counts,
// next to what Embree alone (rtcOccluded16, unpadded quads, no filter: the library's own
// speed) reaches for the same rays. Run: build/benchmarks [--benchmark_filter=scene3]
#include <benchmark/benchmark.h>
#include <embree3/rtcore.h>

#include <numeric>
#include <string>

#include "plain_quads.h"
#include "host/host_threads.h"
#include "host/fast_occluders.h"
#include "host/threaded_assist.h"
#include "radiosity/radiosity_engine.h"
#include "scene/scene_loader.h"

namespace {

ncube::Scene load(const std::string& name) {
  return ncube::load_scene(std::string(NCUBE_SOURCE_DIR) + "/scenes/" + name + ".json");
}

// One iteration each time (the brightest remaining patch shoots), M = 64, on `threads`.
void iteration(benchmark::State& state, const std::string& scene_name, int threads) {
  const ncube::Scene scene = load(scene_name);
  std::vector<int> all(scene.patches.size());
  std::iota(all.begin(), all.end(), 0);
  ncube::RadiosityEngine engine(scene, all);
  ncube::ThreadedAssist assist(threads, nullptr);  // every form factor computed
  engine.use_host_assist(&assist, 0);
  const ncube::FastOccluders occluders(scene, all, ncube::RayTestPolicy::kTestAllPatches, threads);
  ncube::ProgressiveOptions options;
  options.max_iterations = 1;
  options.samples = 64;
  options.host_threads = threads;
  std::uint64_t rays = 0, tests = 0;
  for (auto _ : state) {
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

// The library's own figure: the same rays (every element centre to the 64 parts of the
// first shooter) through plain Embree on one thread, 16 rays of one element per packet.
// With `to_the_end`, an occlusion filter rejects every hit, so Embree follows each ray to its
// end: the library's own cost of a question that a blocker does not settle, as a share's
// "which of the V shares block this ray" is not settled by the first blocker (V > 0).
thread_local std::uint64_t hits_rejected = 0;
void reject_every_hit(const RTCFilterFunctionNArguments* args) {
  for (unsigned i = 0; i < args->N; ++i)
    if (args->valid[i]) {
      args->valid[i] = 0;
      ++hits_rejected;
    }
}

void embree_alone(benchmark::State& state, const std::string& scene_name, bool to_the_end) {
  const ncube::Scene scene = load(scene_name);
  hits_rejected = 0;  // this thread's count, from this run on
  RTCDevice device = rtcNewDevice("threads=1");
  RTCScene rtc_scene =
      ncube::bench::plain_quads(device, scene, to_the_end ? &reject_every_hit : nullptr);
  std::vector<int> all(scene.patches.size());
  std::iota(all.begin(), all.end(), 0);
  const ncube::RadiosityEngine engine(scene, all);
  ncube::WorkCounts unused;
  const ncube::ShooterChoice best = engine.best_shooter(unused);
  const ncube::Shooter shooter = ncube::make_shooter(scene, best.patch, best.unshot, 64);
  std::uint64_t rays = 0, blocked = 0;
  for (auto _ : state) {
    for (const ncube::Element& e : scene.elements) {
      if (e.patch == shooter.patch) continue;
      const ncube::bench::ElementRays traced = ncube::bench::trace_element(rtc_scene, e, shooter);
      rays += traced.rays;
      blocked += traced.blocked;
    }
  }
  state.counters["rays_per_second"] = benchmark::Counter(double(rays), benchmark::Counter::kIsRate);
  // Ratios are each thread's own, averaged over the threads (a plain counter would be summed).
  state.counters["blocked_share"] =
      benchmark::Counter(double(blocked) / double(rays), benchmark::Counter::kAvgThreads);
  if (to_the_end)
    state.counters["hits_per_ray"] =
        benchmark::Counter(double(hits_rejected) / double(rays), benchmark::Counter::kAvgThreads);
  rtcReleaseScene(rtc_scene);
  rtcReleaseDevice(device);
}

BENCHMARK_CAPTURE(iteration, scene1_1thread, std::string("scene1"), 1)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(iteration, scene2_1thread, std::string("scene2"), 1)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(iteration, scene3_1thread, std::string("scene3"), 1)
    ->Unit(benchmark::kMillisecond)->MinTime(3.0)->UseRealTime();
BENCHMARK_CAPTURE(iteration, scene3_all_threads, std::string("scene3"), 0)
    ->Unit(benchmark::kMillisecond)->MinTime(3.0)->UseRealTime();
BENCHMARK_CAPTURE(embree_alone, scene3, std::string("scene3"), false)
    ->Unit(benchmark::kMillisecond)->MinTime(3.0)->UseRealTime();
// The same on two host threads at once (each its own device and scene; the rates are summed):
// the library's rate on the threads of a run of bench/long_runs.py.
BENCHMARK_CAPTURE(embree_alone, scene3_2threads, std::string("scene3"), false)
    ->Unit(benchmark::kMillisecond)->MinTime(3.0)->UseRealTime()->Threads(2);
// Every ray followed to its end on two threads: the library's floor for the shares' question.
BENCHMARK_CAPTURE(embree_alone, scene3_to_the_end_2threads, std::string("scene3"), true)
    ->Unit(benchmark::kMillisecond)->MinTime(3.0)->UseRealTime()->Threads(2);

}  // namespace

// Host speed of the radiosity engine (a reported figure, not a test): host seconds per
// progressive-refinement iteration and shadow rays per second, with exact brute-force counts,
// next to what Embree alone (rtcOccluded16, unpadded quads, no filter: the library's own
// speed) reaches for the same rays. Run: build/benchmarks [--benchmark_filter=scene3]
#include <benchmark/benchmark.h>
#include <embree3/rtcore.h>

#include <numeric>
#include <string>

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
  ncube::ThreadedAssist assist(threads);
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
  RTCDevice device = rtcNewDevice("threads=1");
  RTCScene rtc_scene = rtcNewScene(device);
  RTCGeometry quads = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_QUAD);
  const std::size_t n = scene.patches.size();
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
      quads, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), 4 * n));
  auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
      quads, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT4, 4 * sizeof(unsigned), n));
  for (std::size_t i = 0; i < n; ++i)
    for (int k = 0; k < 4; ++k) {
      const ncube::Polygon& p = scene.patches[i].polygon;
      for (int axis = 0; axis < 3; ++axis)
        vertices[12 * i + 3 * k + axis] = float(p[std::min(k, p.count - 1)][axis]);
      indices[4 * i + k] = unsigned(4 * i + k);
    }
  if (to_the_end) rtcSetGeometryOccludedFilterFunction(quads, &reject_every_hit);
  rtcCommitGeometry(quads);
  rtcAttachGeometry(rtc_scene, quads);
  rtcReleaseGeometry(quads);
  rtcCommitScene(rtc_scene);
  std::vector<int> all(n);
  std::iota(all.begin(), all.end(), 0);
  const ncube::RadiosityEngine engine(scene, all);
  ncube::WorkCounts unused;
  const ncube::ShooterChoice best = engine.best_shooter(unused);
  const ncube::Shooter shooter = ncube::make_shooter(scene, best.patch, best.unshot, 64);
  std::uint64_t rays = 0, blocked = 0;
  for (auto _ : state) {
    for (const ncube::Element& e : scene.elements) {
      if (e.patch == shooter.patch) continue;
      for (int start = 0; start < 64; start += 16) {
        alignas(64) RTCRay16 r;
        alignas(64) int valid[16];
        for (int lane = 0; lane < 16; ++lane) {
          const ncube::Vec3 d = shooter.targets[start + lane] - e.centre;
          // The ray's ends are kept off the receiver and the shooter (no filter here).
          valid[lane] = -1;
          r.org_x[lane] = float(e.centre.x + 1e-4 * d.x);
          r.org_y[lane] = float(e.centre.y + 1e-4 * d.y);
          r.org_z[lane] = float(e.centre.z + 1e-4 * d.z);
          r.dir_x[lane] = float(d.x);
          r.dir_y[lane] = float(d.y);
          r.dir_z[lane] = float(d.z);
          r.tnear[lane] = 0.0f;
          r.tfar[lane] = 1.0f - 2e-4f;
          r.time[lane] = 0.0f;
          r.mask[lane] = ~0u;
          r.id[lane] = unsigned(lane);
          r.flags[lane] = 0;
        }
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
        rtcOccluded16(valid, rtc_scene, &context, &r);
        for (int lane = 0; lane < 16; ++lane) blocked += r.tfar[lane] < 0.0f;
        rays += 16;
      }
    }
  }
  state.counters["rays_per_second"] = benchmark::Counter(double(rays), benchmark::Counter::kIsRate);
  state.counters["blocked_share"] = double(blocked) / double(rays);
  if (to_the_end) state.counters["hits_per_ray"] = double(hits_rejected) / double(rays);
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

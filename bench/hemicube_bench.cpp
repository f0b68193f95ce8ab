// Host speed of the hemicube against the paper's rays (issue 31, item 8; a reported figure,
// not a test): the host seconds of the first 20 shots of a scene on one processor holding
// every patch, on one host thread, with ray-traced form factors (M = 64, the fast brute-force
// occluders and the host's help, as ./simulate runs them with V = 0) and with the hemicube
// (N = 100, at the shooter's centre and at its elements). `hemicube_over_rays` is the ratio
// of host seconds (below 1: the hemicube is faster). Run:
//   build/benchmarks --benchmark_filter=Hemicube
// Measured on scene2 (docs/performance.md does not list it yet): see docs/model.md, "The
// hemicube".
#include <benchmark/benchmark.h>

#include <chrono>
#include <numeric>
#include <string>

#include "host/fast_occluders.h"
#include "host/threaded_assist.h"
#include "radiosity/radiosity_engine.h"
#include "scene/scene_loader.h"
#include "visibility/brute_force_occluders.h"

namespace {

double host_seconds_of_shots(const ncube::Scene& scene, const std::string& form_factors,
                             ncube::HemicubePlacement placement, int shots) {
  std::vector<int> all(scene.patches.size());
  std::iota(all.begin(), all.end(), 0);
  const auto start = std::chrono::steady_clock::now();
  ncube::RadiosityEngine engine(scene, all);
  ncube::ProgressiveOptions options;
  options.max_iterations = shots;
  options.form_factors = form_factors;
  options.hemicube.placement = placement;
  options.host_threads = 1;
  if (form_factors == "ray-traced") {
    ncube::ThreadedAssist assist(1, nullptr);  // every form factor computed
    engine.use_host_assist(&assist, 0);
    const ncube::FastOccluders occluders(scene, all, ncube::RayTestPolicy::kTestAllPatches, 1);
    ncube::run_progressive(engine, occluders, options);
    engine.use_host_assist(nullptr, 0);
  } else {  // the occluders only name the patches: the hemicube traces no rays
    const ncube::BruteForceOccluders occluders(scene, all, ncube::RayTestPolicy::kTestAllPatches);
    ncube::run_progressive(engine, occluders, options);
  }
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void hemicube_against_rays(benchmark::State& state, const std::string& scene_name,
                           ncube::HemicubePlacement placement) {
  const ncube::Scene scene =
      ncube::load_scene(std::string(NCUBE_SOURCE_DIR) + "/scenes/" + scene_name + ".json");
  double rays = 0.0, hemicube = 0.0;
  for (auto _ : state) {
    rays += host_seconds_of_shots(scene, "ray-traced", placement, 20);
    hemicube += host_seconds_of_shots(scene, "hemicube", placement, 20);
  }
  state.counters["ray_traced_seconds"] = benchmark::Counter(rays, benchmark::Counter::kAvgIterations);
  state.counters["hemicube_seconds"] = benchmark::Counter(hemicube, benchmark::Counter::kAvgIterations);
  state.counters["hemicube_over_rays"] = hemicube / rays;
}

}  // namespace

BENCHMARK_CAPTURE(hemicube_against_rays, scene2_centre, "scene2", ncube::HemicubePlacement::kCentre)
    ->Iterations(1)
    ->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(hemicube_against_rays, cornell_box_centre, "cornell-box",
                  ncube::HemicubePlacement::kCentre)
    ->Iterations(1)
    ->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(hemicube_against_rays, cornell_box_elements, "cornell-box",
                  ncube::HemicubePlacement::kElements)
    ->Iterations(1)
    ->Unit(benchmark::kSecond);

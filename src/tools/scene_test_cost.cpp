// What a ray-patch test costs the host in each scene the simulator is held against
// (build/machine_probe --scenes ROUNDS; a reported figure, not a rate written anywhere): the
// paper's brute-force visibility loop (visible_parts over BruteForceOccluders, the code the
// probe times in its rooms and the node programs charge) on the scenes themselves and in the
// probe's own rooms, every run timed round by round in one process so that the host's other
// work falls on all of them alike (docs/machines/probe.md, "Why the runs spread", and "What
// a test costs: the simulated caches and branches").
//
// Runs: the probe's rooms of 19 to 985 patches (machine_probe_main.cpp's, the shots it fits
// test_speed on), then each scene of scenes/ (cornell-box, scene0, scene1, scene2) with its
// patches tested in the scene's own order and in a shuffled order (seed 1994: the same tests
// and crossings, a different sequence of branches and of memory reads). Shooters as the
// probe's: the brightest patch and three spread through the list, 64 parts each; a scene whose
// shots are more than about 1.5e8 counted flops is cut to every k-th receiver. A timed unit is
// as many passes of a run's shots as make about 1.5e8 counted flops; each run's time is the
// median of the rounds' thread-CPU timings; from it the rays' and blocked rays' share at the
// platform's rates is taken off, and what is left over the counted test and crossing flops is
// the test rate the run shows (compare the platform's test_speed). Prints one line per run.
#include "tools/scene_test_cost.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <memory>
#include <random>
#include <regex>
#include <string>
#include <vector>

#include "machine/cost_model.h"
#include "radiosity/radiosity_engine.h"
#include "scene/scene_loader.h"
#include "tools/simulate_options.h"
#include "tools/thread_clock.h"
#include "util/input_error.h"
#include "util/input_file.h"
#include "visibility/brute_force_occluders.h"
#include "visibility/shooter.h"

namespace ncube {
namespace {

double prop(const std::string& file, const std::string& text, const std::string& id) {
  std::smatch m;
  if (!std::regex_search(text, m, std::regex("<prop id=\"" + id + "\" value=\"([0-9.eE+-]+)\"")))
    throw InputError(file + ": no <prop id=\"" + id + "\"> (a probed platform's rates are needed)");
  return std::stod(m[1]);
}

struct SceneShots {
  Scene scene;
  std::unique_ptr<RadiosityEngine> engine;
  std::unique_ptr<BruteForceOccluders> occluders;
  std::vector<Shooter> shooters;
  std::vector<std::vector<ElementRef>> receivers;
  void pass(WorkCounts& c) const {
    for (std::size_t s = 0; s < shooters.size(); ++s)
      visible_parts(*engine, *occluders, receivers[s], shooters[s], c);
  }
};

constexpr double kFlopsAPass = 1.5e8;

// A scene's shots cut to about kFlopsAPass: every k-th receiver (`together` false), or the
// first receivers of each shooter's list, one after another as a whole run meets them.
std::shared_ptr<SceneShots> scene_shots(const std::string& scene_name, bool shuffled, bool together) {
  const std::string root = repository_root();
  const CostModel costs = load_cost_model(root + "/platforms/cost_model.json");
  auto v = std::make_shared<SceneShots>();
  v->scene = load_scene(root + "/scenes/" + scene_name + ".json");
  std::vector<int> all(v->scene.patches.size());
  for (std::size_t k = 0; k < all.size(); ++k) all[k] = int(k);
  v->engine = std::make_unique<RadiosityEngine>(v->scene, all);
  std::vector<int> tested = all;
  if (shuffled) std::shuffle(tested.begin(), tested.end(), std::mt19937(1994));
  v->occluders = std::make_unique<BruteForceOccluders>(v->scene, tested, RayTestPolicy::kTestAllPatches);
  const int n = int(all.size());
  for (int patch : scene_shooter_patches(v->scene)) {
    v->shooters.push_back(make_shooter(v->scene, patch, Rgb(1.0), 64));
    WorkCounts ignored;
    v->receivers.push_back(v->engine->receivers(v->shooters.back(), false, ignored));
  }
  double rays = 0;
  for (std::size_t s = 0; s < v->shooters.size(); ++s)
    rays += double(v->receivers[s].size()) * v->shooters[s].part_count;
  const double estimate = rays * double(n) * costs.flops_per_ray_patch_test;
  if (estimate > kFlopsAPass) {
    const auto stride = std::size_t(std::ceil(estimate / kFlopsAPass));
    for (auto& receivers : v->receivers) {
      std::vector<ElementRef> kept;
      if (together)
        kept.assign(receivers.begin(), receivers.begin() + std::ptrdiff_t((receivers.size() + stride - 1) / stride));
      else
        for (std::size_t k = 0; k < receivers.size(); k += stride) kept.push_back(receivers[k]);
      receivers = kept;
    }
  }
  WorkCounts warm;
  v->pass(warm);  // warms the caches
  return v;
}

double test_flops(const CostModel& costs, const WorkCounts& c) {
  return double(c.ray_patch_tests) * costs.flops_per_ray_patch_test +
         double(c.plane_crossings) * costs.flops_per_plane_crossing;
}

}  // namespace

std::vector<int> scene_shooter_patches(const Scene& scene) {
  int light = 0;
  for (std::size_t k = 0; k < scene.patches.size(); ++k) {
    const auto& e = scene.patches[k].emission;
    const auto& b = scene.patches[std::size_t(light)].emission;
    if (e.r + e.g + e.b > b.r + b.g + b.b) light = int(k);
  }
  std::vector<int> chosen = {light};
  const int n = int(scene.patches.size());
  for (int k = 0; k < 3; ++k) {
    int patch = int(std::lround((k + 0.5) * n / 3 - 0.5));
    while (std::find(chosen.begin(), chosen.end(), patch) != chosen.end()) patch = (patch + 1) % n;
    chosen.push_back(patch);
  }
  return chosen;
}

void time_round_by_round(std::vector<TimedPasses>& runs, int rounds) {
  for (int r = 0; r < rounds; ++r)
    for (TimedPasses& p : runs) {
      WorkCounts c;
      const double t0 = thread_seconds();
      for (int k = 0; k < p.passes; ++k) p.pass(c);
      p.seconds.push_back(thread_seconds() - t0);
    }
}

const LoopRun& named_run(const std::string& option, const std::string& name,
                         const std::vector<LoopRun>& runs) {
  for (const LoopRun& run : runs)
    if (run.name == name) return run;
  std::string names;
  for (const LoopRun& run : runs) names += (names.empty() ? "" : ", ") + run.name;
  throw InputError(option + ": no run \"" + name + "\" (runs: " + names + ")");
}

std::vector<LoopRun> scene_loop_runs() {
  std::vector<LoopRun> runs;
  for (const std::string scene_name : {"cornell-box", "scene0", "scene1", "scene2"})
    for (const bool shuffled : {false, true})
      runs.push_back({scene_name + (shuffled ? " shuffled" : " in order"), [scene_name, shuffled] {
                        std::shared_ptr<SceneShots> shots = scene_shots(scene_name, shuffled, false);
                        return std::function<void(WorkCounts&)>(
                            [shots](WorkCounts& c) { shots->pass(c); });
                      }});
  // The two scenes cut to a share of their receivers: those receivers one after another, as a
  // whole run meets them, instead of every k-th.
  for (const std::string scene_name : {"scene1", "scene2"})
    runs.push_back({scene_name + " receivers together", [scene_name] {
                      std::shared_ptr<SceneShots> shots = scene_shots(scene_name, false, true);
                      return std::function<void(WorkCounts&)>([shots](WorkCounts& c) { shots->pass(c); });
                    }});
  return runs;
}

int print_scene_test_costs(int rounds, const std::string& platform_file,
                           const std::vector<LoopRun>& rooms) {
  const std::string root = repository_root();
  const CostModel costs = load_cost_model(root + "/platforms/cost_model.json");
  const std::string platform = read_input_file(platform_file, kSimgridPlatformFile);
  const double ray_speed = prop(platform_file, platform, "ray_speed"),
               blocked_speed = prop(platform_file, platform, "blocked_ray_speed"),
               test_speed = prop(platform_file, platform, "test_speed");
  std::vector<LoopRun> all = rooms;
  for (LoopRun& run : scene_loop_runs()) all.push_back(std::move(run));
  std::vector<TimedPasses> prepared;
  for (const LoopRun& run : all) {
    TimedPasses p;
    p.name = run.name;
    p.pass = run.prepare();
    p.pass(p.counts);
    p.passes = std::max(1, int(std::lround(kFlopsAPass / test_flops(costs, p.counts))));
    prepared.push_back(std::move(p));
  }
  time_round_by_round(prepared, rounds);
  std::printf("run | tests a ray | crossing share | blocked a ray | passes | median s | spread | "
              "test rate shown, flop/s | over test_speed | ns a test\n");
  for (const TimedPasses& p : prepared) {
    const WorkCounts& c = p.counts;
    const double t = median(p.seconds) / p.passes;
    const double others = double(c.rays) * costs.flops_per_ray / ray_speed +
                          double(c.blocked_rays) * costs.flops_per_blocked_ray / blocked_speed;
    const double rate = test_flops(costs, c) / (t - others);
    const auto [lo, hi] = std::minmax_element(p.seconds.begin(), p.seconds.end());
    std::printf("%s | %.1f | %.3f | %.3f | %d | %.4f | %.1f %% | %.4g | %+.1f %% | %.3f\n", p.name.c_str(),
                double(c.ray_patch_tests) / double(c.rays),
                double(c.plane_crossings) / double(c.ray_patch_tests),
                double(c.blocked_rays) / double(c.rays), p.passes, t * p.passes,
                100 * (*hi - *lo) / median(p.seconds), rate, 100 * (rate / test_speed - 1),
                1e9 * (t - others) / double(c.ray_patch_tests));
  }
  return 0;
}

int run_loop_passes(const std::string& name, int passes, const std::vector<LoopRun>& rooms) {
  std::vector<LoopRun> all = rooms;
  for (LoopRun& run : scene_loop_runs()) all.push_back(std::move(run));
  const std::function<void(WorkCounts&)> pass = named_run("--loop-only", name, all).prepare();
  WorkCounts c;
  for (int k = 0; k < passes; ++k) pass(c);
  std::printf("%s | passes %d | patches_tested_a_ray %.4f | rays %llu | ray_patch_tests %llu | "
              "plane_crossings %llu | blocked_rays %llu\n",
              name.c_str(), passes, double(c.ray_patch_tests) / double(c.rays),
              (unsigned long long)(c.rays / std::uint64_t(passes)),
              (unsigned long long)(c.ray_patch_tests / std::uint64_t(passes)),
              (unsigned long long)(c.plane_crossings / std::uint64_t(passes)),
              (unsigned long long)(c.blocked_rays / std::uint64_t(passes)));
  return 0;
}

}  // namespace ncube

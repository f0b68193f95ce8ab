// What a ray-patch test costs the host in each scene the simulator is held against
// (build/machine_probe --scenes ROUNDS; a reported figure, not a rate written anywhere): the
// paper's brute-force visibility loop (visible_parts over BruteForceOccluders, the code the
// probe times in its rooms and the node programs charge) on the scenes themselves, every
// variant timed round by round in one process so that the host's other work falls on all of
// them alike (docs/machines/probe.md, "Why the runs spread").
//
// Variants: each scene of scenes/ (cornell-box, scene0, scene1, scene2) with its patches tested
// in the scene's own order and in a shuffled order (seed 1994: the same tests and crossings, a
// different sequence of branches and of memory reads). Shooters as the probe's: the brightest
// patch and three spread through the list, 64 parts each; a scene whose shots are more than
// about 1.5e8 counted flops is cut to every k-th receiver. Each variant's time is the median of
// the rounds' thread-CPU timings; from it the rays' and blocked rays' share at the platform's
// rates is taken off, and what is left over the counted test and crossing flops is the test
// rate the scene shows (compare the platform's test_speed). Prints one line per variant.
#include "tools/scene_test_cost.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <memory>
#include <stdexcept>
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

struct Variant {
  std::string name;
  ncube::Scene scene;
  std::unique_ptr<ncube::RadiosityEngine> engine;
  std::unique_ptr<ncube::BruteForceOccluders> occluders;
  std::vector<ncube::Shooter> shooters;
  std::vector<std::vector<ncube::ElementRef>> receivers;
  ncube::WorkCounts counts;  // of one pass
  std::vector<double> seconds;
  void pass(ncube::WorkCounts& c) const {
    for (std::size_t s = 0; s < shooters.size(); ++s)
      ncube::visible_parts(*engine, *occluders, receivers[s], shooters[s], c);
  }
};

constexpr double kFlopsAPass = 1.5e8;

}  // namespace

int print_scene_test_costs(int rounds, const std::string& platform_file) {
  const std::string root = ncube::repository_root();
  const ncube::CostModel costs = ncube::load_cost_model(root + "/platforms/cost_model.json");
  const std::string platform = ncube::read_input_file(platform_file, ncube::kSimgridPlatformFile);
  const double ray_speed = prop(platform_file, platform, "ray_speed"),
               blocked_speed = prop(platform_file, platform, "blocked_ray_speed"),
               test_speed = prop(platform_file, platform, "test_speed");
  std::vector<std::unique_ptr<Variant>> variants;
  for (const std::string scene_name : {"cornell-box", "scene0", "scene1", "scene2"}) {
    for (const bool shuffled : {false, true}) {
      auto v = std::make_unique<Variant>();
      v->name = scene_name + (shuffled ? " shuffled" : " in order");
      v->scene = ncube::load_scene(root + "/scenes/" + scene_name + ".json");
      std::vector<int> all(v->scene.patches.size());
      for (std::size_t k = 0; k < all.size(); ++k) all[k] = int(k);
      v->engine = std::make_unique<ncube::RadiosityEngine>(v->scene, all);
      std::vector<int> tested = all;
      if (shuffled) std::shuffle(tested.begin(), tested.end(), std::mt19937(1994));
      v->occluders = std::make_unique<ncube::BruteForceOccluders>(
          v->scene, tested, ncube::RayTestPolicy::kTestAllPatches);
      int light = 0;
      for (std::size_t k = 0; k < v->scene.patches.size(); ++k) {
        const auto& e = v->scene.patches[k].emission;
        const auto& b = v->scene.patches[std::size_t(light)].emission;
        if (e.r + e.g + e.b > b.r + b.g + b.b) light = int(k);
      }
      std::vector<int> chosen = {light};
      const int n = int(all.size());
      for (int k = 0; k < 3; ++k) {
        int patch = int(std::lround((k + 0.5) * n / 3 - 0.5));
        while (std::find(chosen.begin(), chosen.end(), patch) != chosen.end()) patch = (patch + 1) % n;
        chosen.push_back(patch);
      }
      for (int patch : chosen) {
        v->shooters.push_back(ncube::make_shooter(v->scene, patch, ncube::Rgb(1.0), 64));
        ncube::WorkCounts ignored;
        v->receivers.push_back(v->engine->receivers(v->shooters.back(), false, ignored));
      }
      double rays = 0;
      for (std::size_t s = 0; s < v->shooters.size(); ++s)
        rays += double(v->receivers[s].size()) * v->shooters[s].part_count;
      const double estimate = rays * double(n) * costs.flops_per_ray_patch_test;
      if (estimate > kFlopsAPass) {
        const auto stride = std::size_t(std::ceil(estimate / kFlopsAPass));
        for (auto& receivers : v->receivers) {
          std::vector<ncube::ElementRef> kept;
          for (std::size_t k = 0; k < receivers.size(); k += stride) kept.push_back(receivers[k]);
          receivers = kept;
        }
      }
      v->pass(v->counts);  // warms the caches, counts a pass
      variants.push_back(std::move(v));
    }
  }
  for (int r = 0; r < rounds; ++r)
    for (auto& v : variants) {
      ncube::WorkCounts c;
      const double t0 = thread_seconds();
      v->pass(c);
      v->seconds.push_back(thread_seconds() - t0);
    }
  std::printf("scene, patches' order | patches | tests a ray | crossing share | blocked a ray | median s | spread | "
              "test rate shown, flop/s | over test_speed | ns a test\n");
  for (const auto& v : variants) {
    const ncube::WorkCounts& c = v->counts;
    const double t = median(v->seconds);
    const double others = c.rays * costs.flops_per_ray / ray_speed +
                          c.blocked_rays * costs.flops_per_blocked_ray / blocked_speed;
    const double test_flops = c.ray_patch_tests * costs.flops_per_ray_patch_test +
                              c.plane_crossings * costs.flops_per_plane_crossing;
    const double rate = test_flops / (t - others);
    const auto [lo, hi] = std::minmax_element(v->seconds.begin(), v->seconds.end());
    std::printf("%s | %zu | %.1f | %.3f | %.3f | %.4f | %.1f %% | %.4g | %+.1f %% | %.3f\n",
                v->name.c_str(), v->scene.patches.size(), double(c.ray_patch_tests) / double(c.rays),
                double(c.plane_crossings) / double(c.ray_patch_tests), double(c.blocked_rays) / double(c.rays),
                t, 100 * (*hi - *lo) / t, rate, 100 * (rate / test_speed - 1),
                1e9 * (t - others) / double(c.ray_patch_tests));
  }
  return 0;
}

}  // namespace ncube

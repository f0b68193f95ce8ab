// The ray-tracing library's floor for a run's own rays (a reported figure, not a test): every
// distinct shooter of a result file, each element centre (but those on the shooter) to its M
// ray targets, through plain Embree (rtcOccluded16, unpadded quads, 16 rays of one element per
// packet, as build/benchmarks embree_alone), on two host threads. Twice: to the first hit
// (the question of V = 0) and following every ray to its end through an occlusion filter that
// rejects every hit (the shares' question when V > 0). A repeated shot of the run asks the
// same rays again; the simulator answers those from its answer cache, so the distinct shots
// are the library's work.
//
//   build/embree_floor RESULT.json [first-hit|to-the-end]
//
// Prints one line per mode (both unless one is named): distinct shots, rays, seconds, rays per
// second, hits per ray; and the seconds alone as the last word of the line.
#include <embree3/rtcore.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "plain_quads.h"
#include "scene/scene_loader.h"
#include "util/input_error.h"
#include "util/input_file.h"
#include "visibility/shooter.h"

namespace {

std::atomic<std::uint64_t> hits_seen{0};

void reject_every_hit(const RTCFilterFunctionNArguments* args) {
  std::uint64_t hits = 0;
  for (unsigned i = 0; i < args->N; ++i)
    if (args->valid[i]) {
      args->valid[i] = 0;
      ++hits;
    }
  hits_seen.fetch_add(hits, std::memory_order_relaxed);
}

// The rays of one shot: every element not on the shooter to each of its targets.
std::uint64_t trace_shot(RTCScene rtc_scene, const ncube::Scene& scene, const ncube::Shooter& shooter) {
  std::uint64_t rays = 0;
  for (const ncube::Element& e : scene.elements)
    if (e.patch != shooter.patch) rays += ncube::bench::trace_element(rtc_scene, e, shooter).rays;
  return rays;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string mode = argc == 3 ? argv[2] : "both";
  if (argc < 2 || argc > 3 || (mode != "both" && mode != "first-hit" && mode != "to-the-end")) {
    std::fprintf(stderr, "usage: embree_floor RESULT.json [first-hit|to-the-end]\n");
    return 2;
  }
  std::string text;
  try {
    text = ncube::read_input_file(argv[1], ncube::kResultFile);
  } catch (const ncube::InputError& e) {
    std::fprintf(stderr, "embree_floor: %s\n", e.what());
    return 3;
  }
  const nlohmann::json result = nlohmann::json::parse(text);
  const ncube::Scene scene = ncube::load_scene(result["provenance"]["scene"]["file"].get<std::string>());
  const int samples = result["config"]["samples"].get<int>();
  const std::vector<int> shots = result["shooters"].get<std::vector<int>>();
  const std::set<int> distinct_set(shots.begin(), shots.end());
  const std::vector<int> distinct(distinct_set.begin(), distinct_set.end());
  std::vector<ncube::Shooter> shooters;
  for (const int patch : distinct) shooters.push_back(ncube::make_shooter(scene, patch, ncube::Rgb(0.0), samples));
  for (const bool to_the_end : {false, true}) {
    if (mode == (to_the_end ? "first-hit" : "to-the-end")) continue;
    RTCDevice device = rtcNewDevice("threads=1");
    RTCScene rtc_scene = ncube::bench::plain_quads(device, scene, to_the_end ? &reject_every_hit : nullptr);
    hits_seen = 0;
    std::atomic<std::size_t> next{0};
    std::atomic<std::uint64_t> rays{0};
    const auto start = std::chrono::steady_clock::now();
    std::vector<std::thread> threads;
    for (int t = 0; t < 2; ++t)
      threads.emplace_back([&] {
        for (std::size_t i; (i = next++) < shooters.size();)
          rays += trace_shot(rtc_scene, scene, shooters[i]);
      });
    for (std::thread& t : threads) t.join();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("%s: %zu distinct shots of %zu, %llu rays, %.1f s on 2 threads, %.1f M rays/s",
                to_the_end ? "to the end of every ray" : "to the first hit", shooters.size(),
                shots.size(), static_cast<unsigned long long>(rays.load()), seconds,
                double(rays) / seconds / 1e6);
    if (to_the_end) std::printf(", %.2f hits per ray", double(hits_seen) / double(rays));
    std::printf(", seconds %.3f\n", seconds);
    rtcReleaseScene(rtc_scene);
    rtcReleaseDevice(device);
  }
  return 0;
}

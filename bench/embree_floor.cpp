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
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "radiosity/shooter.h"
#include "scene/scene_loader.h"

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

RTCScene quad_scene(RTCDevice device, const ncube::Scene& scene, bool to_the_end) {
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
  return rtc_scene;
}

// The rays of one shot: every element not on the shooter to each of its targets.
std::uint64_t trace_shot(RTCScene rtc_scene, const ncube::Scene& scene, const ncube::Shooter& shooter) {
  std::uint64_t rays = 0;
  const int m = shooter.part_count;
  for (const ncube::Element& e : scene.elements) {
    if (e.patch == shooter.patch) continue;
    for (int start = 0; start < m; start += 16) {
      alignas(64) RTCRay16 r;
      alignas(64) int valid[16];
      for (int lane = 0; lane < 16; ++lane) {
        const int k = std::min(start + lane, m - 1);
        const ncube::Vec3 d = shooter.targets[std::size_t(k)] - e.centre;
        valid[lane] = start + lane < m ? -1 : 0;
        // The ray's ends kept off the receiver and the shooter (no exact test here).
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
      rays += std::uint64_t(std::min(16, m - start));
    }
  }
  return rays;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string mode = argc == 3 ? argv[2] : "both";
  if (argc < 2 || argc > 3 || (mode != "both" && mode != "first-hit" && mode != "to-the-end")) {
    std::fprintf(stderr, "usage: embree_floor RESULT.json [first-hit|to-the-end]\n");
    return 2;
  }
  std::ifstream in(argv[1]);
  if (!in) {
    std::fprintf(stderr, "embree_floor: cannot read %s\n", argv[1]);
    return 3;
  }
  const nlohmann::json result = nlohmann::json::parse(in);
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
    RTCScene rtc_scene = quad_scene(device, scene, to_the_end);
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
    std::printf("%s: %zu distinct shots of %zu, %.3g rays, %.1f s on 2 threads, %.1f M rays/s",
                to_the_end ? "to the end of every ray" : "to the first hit", shooters.size(),
                shots.size(), double(rays), seconds, double(rays) / seconds / 1e6);
    if (to_the_end) std::printf(", %.2f hits per ray", double(hits_seen) / double(rays));
    std::printf(", seconds %.3f\n", seconds);
    rtcReleaseScene(rtc_scene);
    rtcReleaseDevice(device);
  }
  return 0;
}

// The ray-tracing library's own view of a scene for the floors the benchmarks report
// (build/benchmarks embree_alone, build/embree_floor): every patch as one plain Embree quad
// (a triangle as a quad with its last corner repeated), unpadded, no exact test. With a
// filter (e.g. one that rejects every hit) the occlusion query follows each ray to its end.
#pragma once

#include <embree3/rtcore.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>

#include "scene/scene.h"
#include "visibility/shooter.h"

namespace ncube::bench {

inline RTCScene plain_quads(RTCDevice device, const Scene& scene,
                            RTCFilterFunctionN occluded_filter = nullptr) {
  RTCScene rtc_scene = rtcNewScene(device);
  RTCGeometry quads = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_QUAD);
  const std::size_t n = scene.patches.size();
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
      quads, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), 4 * n));
  auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
      quads, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT4, 4 * sizeof(unsigned), n));
  for (std::size_t i = 0; i < n; ++i)
    for (int k = 0; k < 4; ++k) {
      const Polygon& p = scene.patches[i].polygon;
      for (int axis = 0; axis < 3; ++axis)
        vertices[12 * i + 3 * k + axis] = float(p[std::min(k, p.count - 1)][axis]);
      indices[4 * i + k] = unsigned(4 * i + k);
    }
  if (occluded_filter) rtcSetGeometryOccludedFilterFunction(quads, occluded_filter);
  rtcCommitGeometry(quads);
  rtcAttachGeometry(rtc_scene, quads);
  rtcReleaseGeometry(quads);
  rtcCommitScene(rtc_scene);
  return rtc_scene;
}

// The rays of one element to the shooter's M targets, 16 per rtcOccluded16 call, their ends
// kept off the receiver and the shooter by a small margin (no exact test here). Returns
// the rays traced; adds those reported blocked to `blocked`.
struct ElementRays {
  std::uint64_t rays = 0, blocked = 0;
};
inline ElementRays trace_element(RTCScene rtc_scene, const Element& e, const Shooter& shooter) {
  ElementRays out;
  const int m = shooter.part_count;
  for (int start = 0; start < m; start += 16) {
    alignas(64) RTCRay16 r;
    alignas(64) int valid[16];
    for (int lane = 0; lane < 16; ++lane) {
      const int k = std::min(start + lane, m - 1);  // idle lanes repeat the last ray
      const Vec3 d = shooter.targets[std::size_t(k)] - e.centre;
      valid[lane] = start + lane < m ? -1 : 0;
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
    for (int lane = 0; lane < 16; ++lane) out.blocked += valid[lane] && r.tfar[lane] < 0.0f;
    out.rays += std::uint64_t(std::min(16, m - start));
  }
  return out;
}

}  // namespace ncube::bench

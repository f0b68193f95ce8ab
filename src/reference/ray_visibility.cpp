#include "reference/ray_visibility.h"

#include <cmath>
#include <stdexcept>
#include <glm/geometric.hpp>
#include <string>

namespace ncube::reference {

RayVisibility::RayVisibility(const Scene& scene) {
  lift_ = kLift * scene_bounds(scene).diagonal();
  device_ = rtcNewDevice("set_affinity=0");
  if (!device_) throw std::runtime_error("Embree: no device (error " +
                                         std::to_string(int(rtcGetDeviceError(nullptr))) + ")");
  scene_ = rtcNewScene(device_);
  rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);
  RTCGeometry triangles = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
  std::size_t triangle_count = 0;
  for (const Patch& patch : scene.patches) triangle_count += std::size_t(patch.polygon.count - 2);
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
      triangles, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float),
      3 * triangle_count));
  auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
      triangles, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned),
      triangle_count));
  std::size_t t = 0;
  for (const Patch& patch : scene.patches)
    for (int k = 1; k + 1 < patch.polygon.count; ++k, ++t) {  // a fan: (0,1,2), (0,2,3)
      triangle_normals_.push_back(patch.normal);
      const Vec3 corners[3] = {patch.polygon[0], patch.polygon[k], patch.polygon[k + 1]};
      for (int c = 0; c < 3; ++c) {
        for (int axis = 0; axis < 3; ++axis)
          vertices[9 * t + 3 * std::size_t(c) + std::size_t(axis)] = float(corners[c][axis]);
        indices[3 * t + std::size_t(c)] = unsigned(3 * t + std::size_t(c));
      }
    }
  rtcCommitGeometry(triangles);
  rtcAttachGeometry(scene_, triangles);
  rtcReleaseGeometry(triangles);
  rtcCommitScene(scene_);
}

RayVisibility::~RayVisibility() {
  if (scene_) rtcReleaseScene(scene_);
  if (device_) rtcReleaseDevice(device_);
}

bool RayVisibility::visible(const Vec3& a, const Vec3& na, const Vec3& b, const Vec3& nb) const {
  const Vec3 from = a + lift_ * na;
  const Vec3 to = b + lift_ * nb;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay ray{};
  ray.org_x = float(from.x);
  ray.org_y = float(from.y);
  ray.org_z = float(from.z);
  ray.dir_x = float(to.x - from.x);
  ray.dir_y = float(to.y - from.y);
  ray.dir_z = float(to.z - from.z);
  ray.tnear = 0.0f;
  ray.tfar = 1.0f;
  ray.mask = 0xFFFFFFFFu;
  ray.flags = 0;
  rtcOccluded1(scene_, &context, &ray);
  return ray.tfar >= 0.0f;  // Embree sets tfar to -inf when the ray is blocked
}

}  // namespace ncube::reference

namespace ncube::reference {

RayVisibility::Hit RayVisibility::first_hit(const Vec3& a, const Vec3& na,
                                            const Vec3& direction) const {
  const Vec3 from = a + lift_ * na;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit hit{};
  hit.ray.org_x = float(from.x);
  hit.ray.org_y = float(from.y);
  hit.ray.org_z = float(from.z);
  hit.ray.dir_x = float(direction.x);
  hit.ray.dir_y = float(direction.y);
  hit.ray.dir_z = float(direction.z);
  hit.ray.tnear = 0.0f;
  hit.ray.tfar = INFINITY;
  hit.ray.mask = 0xFFFFFFFFu;
  hit.ray.flags = 0;
  hit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene_, &context, &hit);
  if (hit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return Hit::kNothing;
  return glm::dot(triangle_normals_[hit.hit.primID], direction) < 0.0 ? Hit::kFront : Hit::kBack;
}

}  // namespace ncube::reference

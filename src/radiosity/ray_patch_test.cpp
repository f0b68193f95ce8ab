#include "radiosity/ray_patch_test.h"

#include <glm/geometric.hpp>

namespace ncube {

PatchCandidate make_candidate(const Polygon& polygon, const Vec3& normal, int scene_index) {
  PatchCandidate c{};
  c.vertex_count = polygon.count;
  for (int i = 0; i < polygon.count; ++i) c.vertices[i] = polygon[i];
  c.normal = normal;
  c.plane_offset = glm::dot(normal, polygon[0]);
  c.scene_index = scene_index;
  return c;
}

bool segment_crosses(const PatchCandidate& c, const Vec3& from, const Vec3& delta) {
  const double denominator = glm::dot(c.normal, delta);
  if (denominator == 0.0) return false;  // parallel to the plane
  const double t = (c.plane_offset - glm::dot(c.normal, from)) / denominator;
  if (!(t > kRayEpsilon && t < 1.0 - kRayEpsilon)) return false;
  const Vec3 x = from + t * delta;
  for (int k = 0; k < c.vertex_count; ++k) {
    const Vec3& a = c.vertices[k];
    const Vec3& b = c.vertices[(k + 1) % c.vertex_count];
    if (glm::dot(c.normal, glm::cross(b - a, x - a)) < 0.0) return false;
  }
  return true;
}

}  // namespace ncube

#include "visibility/ray_patch_test.h"


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

}  // namespace ncube

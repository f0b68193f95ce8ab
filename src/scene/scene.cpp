#include "scene/scene.h"

#include <cmath>
#include <glm/geometric.hpp>

namespace ncube {

double luminance(const Rgb& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

void Scene::derive_patch_fields() {
  int first = 0;
  for (Patch& patch : patches) {
    patch.normal = patch.polygon.normal();
    patch.area = patch.polygon.area();
    patch.first_element = first;
    first += patch.element_count();
  }
}

void Scene::build_elements() {
  derive_patch_fields();
  elements.clear();
  elements.reserve(std::size_t(element_total()));
  for (int index = 0; index < int(patches.size()); ++index) {
    const Patch& patch = patches[index];
    for (int j = 0; j < patch.nv; ++j)
      for (int i = 0; i < patch.nu; ++i) {
        Element e;
        e.polygon = grid_cell(patch.polygon, patch.nu, patch.nv, i, j);
        e.patch = index;
        e.centre = e.polygon.centroid();
        e.area = e.polygon.area();
        elements.push_back(e);
      }
  }
}

long Scene::element_total() const {
  long total = 0;
  for (const Patch& p : patches) total += p.element_count();
  return total;
}

double Scene::emitted_power() const {
  double power = 0.0;
  for (const Patch& p : patches) power += (p.emission.r + p.emission.g + p.emission.b) * p.area;
  return power;
}

Bounds scene_bounds(const Scene& scene) {
  Vec3 lo(INFINITY), hi(-INFINITY);
  for (const Patch& p : scene.patches)
    for (int i = 0; i < p.polygon.count; ++i) {
      lo = glm::min(lo, p.polygon[i]);
      hi = glm::max(hi, p.polygon[i]);
    }
  return {lo, hi};
}

Camera default_camera(const Scene& scene) {
  // Scenes are interiors, so the default view stands just inside the +z face of the bounding
  // box, at mid height, and looks across the room towards the -z face (y is up).
  const auto [lo, hi] = scene_bounds(scene);
  const Vec3 centre = 0.5 * (lo + hi);
  Camera camera;
  camera.eye = Vec3(centre.x, centre.y, hi.z - 0.02 * (hi.z - lo.z));
  camera.look_at = Vec3(centre.x, centre.y, lo.z);
  camera.up = Vec3(0.0, 1.0, 0.0);
  camera.fov_deg = 55.0;
  return camera;
}

}  // namespace ncube

// The scene as the radiosity engine sees it: patches (which shoot) cut into elements
// (which receive), the two-level hierarchy of the paper's section 4.
#pragma once

#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "geometry/polygon.h"

namespace ncube {

using Rgb = glm::dvec3;

// Luminance of a radiosity (Rec. 709 weights): the exposure and the subdivision criterion.
double luminance(const Rgb& c);

struct Camera {
  Vec3 eye{0.0};
  Vec3 look_at{0.0, 0.0, -1.0};
  Vec3 up{0.0, 1.0, 0.0};
  double fov_deg = 55.0;  // vertical field of view
};

struct Patch {
  Polygon polygon;
  Rgb reflectance{0.0};
  Rgb emission{0.0};
  int nu = 1, nv = 1;  // the patch is cut into nu x nv elements (see grid_cell)
  // Derived when the scene is built.
  Vec3 normal{0.0};
  double area = 0.0;
  int first_element = 0;  // elements of this patch are [first_element, first_element + nu*nv)
  int element_count() const { return nu * nv; }
};

struct Element {
  Polygon polygon;
  int patch = 0;
  Vec3 centre{0.0};  // the element's visibility point (paper section 4)
  double area = 0.0;
};

struct Scene {
  std::string name;
  Camera camera;
  std::vector<Patch> patches;
  std::vector<Element> elements;

  // Fills each patch's derived fields (normal, area, first element) from its polygon and
  // subdivision; call after the patches are set.
  void derive_patch_fields();
  // The same, and the element list.
  void build_elements();
  // Number of elements of all patches (also before build_elements).
  long element_total() const;
  // Total emitted power, sum over patches of (r+g+b) * area.
  double emitted_power() const;
};

// The axis-aligned box around all patches (lo > hi when there are none).
struct Bounds {
  Vec3 lo, hi;
  double diagonal() const { return lo.x <= hi.x ? glm::length(hi - lo) : 0.0; }
};
Bounds scene_bounds(const Scene& scene);

// A default camera that sees the whole scene: from the front of the bounding box, looking
// at its centre. Used when the scene file has no "camera".
Camera default_camera(const Scene& scene);

}  // namespace ncube

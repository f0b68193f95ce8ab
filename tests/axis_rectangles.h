// Axis-aligned rectangles as the scene loader makes them (normalised cross-product normals,
// often +-1 only up to rounding), shared by tests/axis_patch_test.cpp and
// tests/octree_lanes_test.cpp; and points to aim rays at on them.
#pragma once

#include <cmath>
#include <glm/geometric.hpp>
#include <random>
#include <vector>

#include "visibility/ray_patch_test.h"

namespace ncube {

// Axis-aligned rectangles in every orientation, both facings, with awkward sizes and offsets.
inline std::vector<PatchCandidate> rectangles() {
  std::vector<PatchCandidate> out;
  const double offsets[] = {0.0, 0.1, -0.3, 7.000000000000001, 12.6};
  const double sizes[][2] = {{0.025, 0.035}, {0.1, 0.3}, {5.0, 4.0}, {1.0 / 3.0, 0.7}};
  for (int axis = 0; axis < 3; ++axis)
    for (double offset : offsets)
      for (const auto& size : sizes)
        for (int facing = 0; facing < 2; ++facing) {
          const int u = (axis + 1) % 3, v = (axis + 2) % 3;
          Vec3 corner[4];
          for (int k = 0; k < 4; ++k) {
            corner[k][axis] = offset;
            corner[k][u] = 0.2 + ((k == 1 || k == 2) ? size[0] : 0.0);
            corner[k][v] = -0.1 + ((k >= 2) ? size[1] : 0.0);
          }
          const Polygon polygon = facing ? Polygon::quad(corner[0], corner[1], corner[2], corner[3])
                                         : Polygon::quad(corner[3], corner[2], corner[1], corner[0]);
          const Vec3 normal = glm::normalize(glm::cross(polygon[1] - polygon[0], polygon[2] - polygon[0]));
          out.push_back(make_candidate(polygon, normal, int(out.size())));
        }
  return out;
}

// Points around a rectangle's corners and edges: the corner or edge point itself and the
// doubles next to it, in the plane.
inline std::vector<Vec3> aim_points(const PatchCandidate& c, std::mt19937_64& random) {
  std::vector<Vec3> out;
  std::uniform_real_distribution<double> along(0.0, 1.0);
  for (int k = 0; k < 4; ++k) {
    const Vec3& a = c.vertices[k];
    const Vec3& b = c.vertices[(k + 1) % 4];
    const Vec3 on_edge = a + along(random) * (b - a);
    for (const Vec3& base : {a, on_edge, 0.5 * (a + b)})
      for (int axis = 0; axis < 3; ++axis)
        for (int step = -2; step <= 2; ++step) {
          Vec3 p = base;
          for (int s = 0; s < std::abs(step); ++s)
            p[axis] = std::nextafter(p[axis], step > 0 ? 1e300 : -1e300);
          out.push_back(p);
        }
  }
  return out;
}

}  // namespace ncube

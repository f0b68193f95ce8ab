// A scene small enough to count every operation, message and byte of a run by hand
// (tests/simulation_test.cpp, tests/memory_plan_test.cpp).
#pragma once

#include "scene/scene.h"

namespace ncube {

inline Patch hand_counted_patch(const Vec3& origin, const Vec3& u, const Vec3& v, double emission, int nu, int nv) {
  Patch p;
  p.polygon = Polygon::quad(origin, origin + u, origin + u + v, origin + v);
  p.reflectance = Rgb(0.5);
  p.emission = Rgb(emission);
  p.nu = nu;
  p.nv = nv;
  return p;
}

// Patch 0: the light, y = 2 over x, z in [0, 1], facing down, 1 element.
// Patch 1: the floor under it, y = 0, facing up, 5 x 1 elements (centres x = 0.1 .. 0.9).
// Patch 2: a table top, y = 1 over x in [2, 3], facing up, 3 x 1 elements.
// Patch 3: a wall, x = 5, y in [0, 1.6], facing -x, 1 x 2 elements (centres y = 0.4, 1.2).
// Only the light emits, so with --iterations 1 it is the one shooter; the receivers are the
// 10 other elements, and with 4 samples each traces 4 rays to targets at y = 2.
inline Scene hand_counted_scene() {
  const Vec3 X(1, 0, 0), Y(0, 1, 0), Z(0, 0, 1);
  Scene s;
  s.name = "hand-counted";
  s.patches = {hand_counted_patch({0, 2, 0}, X, Z, 1.0, 1, 1), hand_counted_patch({0, 0, 0}, Z, X, 0.0, 1, 5),
               hand_counted_patch({2, 1, 0}, Z, X, 0.0, 1, 3), hand_counted_patch({5, 0, 0}, Z, 1.6 * Y, 0.0, 1, 2)};
  s.build_elements();
  return s;
}

}  // namespace ncube

// Scenes whose octrees and walks are worked out by hand (tests/octree_test.cpp,
// tests/fast_octree_test.cpp).
#pragma once

#include <vector>

#include "hand_counted_scene.h"

namespace ncube {

// Patch 0 (A): the floor y = 0 over x, z in [0, 1]. Patch 1 (B): the wall x = 4 over y, z in
// [0, 1]. Root cell (grown by a pad of 1e-9 x scale, ignored below): x in [0, 4], y, z in
// [0, 1]; its centre (2, 0.5, 0.5). Child index bit 0 is the upper x half, bit 1 y, bit 2 z.
// With max depth 1 and at most 1 patch per leaf the root is split once:
//   A's box (x [0, 1], y [0, 0], z [0, 1]) overlaps children 0 and 4;
//   B's box (x [4, 4], y [0, 1], z [0, 1]) overlaps children 1, 3, 5 and 7.
// Build: 9 cells, 2 patches x 8 children = 16 overlap tests, 2 + 4 = 6 references, 8 leaves.
inline Scene two_patch_scene() {
  const Vec3 X(1, 0, 0), Y(0, 1, 0), Z(0, 0, 1);
  Scene s;
  s.name = "two-patch";
  s.patches = {hand_counted_patch({0, 0, 0}, Z, X, 0.0, 1, 1),
               hand_counted_patch({4, 0, 0}, Y, Z, 0.0, 1, 1)};
  s.build_elements();
  return s;
}

// The default build parameters (max depth 8, at most 8 patches per leaf), worked by hand on a
// cluster: nine squares of side 1e-4 stacked at y = 0, 1e-5, ..., 8e-5 over x, z in [0, 1e-4]
// (positions 0 .. 8), and one more square at y = 1 over x, z in [1, 1.0001] (position 9).
// The root (x, z in [0, 1.0001], y in [0, 1], grown by a pad of 1e-9 x scale) holds 10 > 8
// patches: split. The cluster lies in child 0 at every depth (its 1e-4 is below the
// 1.0001 / 2^9 of a depth-8 cell's half), the far square in the root's child 7, the other
// children are empty. So child 0 is split again at depths 1 .. 7 (9 > 8 patches) and its
// depth-8 child is a leaf because of the depth limit: 8 splits, 1 + 8 x 8 = 65 cells,
// 10 x 8 + 7 x 9 x 8 = 584 overlap tests, 65 - 8 = 57 leaves, 9 + 1 = 10 references.
inline Scene cluster_scene(int cluster) {
  const Vec3 X(1e-4, 0, 0), Z(0, 0, 1e-4);
  Scene s;
  s.name = "cluster";
  for (int k = 0; k < cluster; ++k) s.patches.push_back(hand_counted_patch({0, 1e-5 * k, 0}, Z, X, 0.0, 1, 1));
  s.patches.push_back(hand_counted_patch({1, 1, 1}, Z, X, 0.0, 1, 1));
  s.build_elements();
  return s;
}

inline std::vector<int> every_patch(const Scene& scene) {
  std::vector<int> all(scene.patches.size());
  for (int p = 0; p < int(all.size()); ++p) all[std::size_t(p)] = p;
  return all;
}

}  // namespace ncube

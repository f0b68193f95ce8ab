// --merge-coplanar (src/models/coplanar_merge.h) against the scan it replaced: every
// triangle, in order, takes the first later triangle of its material that shares one of its
// edges (reversed) and makes a planar convex quad with it. On random meshes (grids of quads
// cut along either diagonal, some corners lifted off the plane, corners at 0 and -0, two
// materials, some quads and repeated triangles, in shuffled order) the merges are the scan's
// to the corner; and the halves of a square give back the square.
#include "models/coplanar_merge.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "models/face_shapes.h"

namespace ncube::models {
namespace {

// The merge as a plain scan over every later patch: quadratic, the reference.
std::vector<ImportedPatch> scan_reference(const std::vector<ImportedPatch>& patches, long& pairs) {
  std::vector<bool> used(patches.size(), false);
  std::vector<ImportedPatch> out;
  for (std::size_t i = 0; i < patches.size(); ++i) {
    if (used[i]) continue;
    used[i] = true;
    const ImportedPatch& first = patches[i];
    bool done = false;
    for (std::size_t j = i + 1; j < patches.size() && first.corners.size() == 3 && !done; ++j) {
      const ImportedPatch& second = patches[j];
      if (used[j] || second.corners.size() != 3 || second.material.reflectance != first.material.reflectance ||
          second.material.emission != first.material.emission)
        continue;
      for (std::size_t e = 0; e < 3 && !done; ++e)
        for (std::size_t f = 0; f < 3 && !done; ++f) {
          if (second.corners[f] != first.corners[(e + 1) % 3] || second.corners[(f + 1) % 3] != first.corners[e])
            continue;
          std::vector<Point> quad;
          for (std::size_t k = 0; k < 3; ++k) {
            quad.push_back(first.corners[k]);
            if (k == e) quad.push_back(second.corners[(f + 2) % 3]);
          }
          if (!planar_convex_quad(quad)) continue;
          out.push_back({quad, first.material});
          used[j] = done = true;
          ++pairs;
        }
    }
    if (!done) out.push_back(first);
  }
  return out;
}

std::vector<ImportedPatch> random_mesh(std::mt19937& random, int n) {
  std::uniform_int_distribution<int> coin(0, 1), die(0, 9);
  Material grey, lamp;
  lamp.emission = Point(1.0);
  // Corner (x, y) of the grid, on the plane z = 0 (written -0 at random), a few lifted.
  std::vector<Point> corner;
  for (int y = 0; y <= n; ++y)
    for (int x = 0; x <= n; ++x)
      corner.emplace_back(x, y, die(random) == 0 ? 0.25 : coin(random) ? -0.0 : 0.0);
  const auto at = [&](int x, int y) { return corner[std::size_t(y * (n + 1) + x)]; };
  std::vector<ImportedPatch> mesh;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const Point a = at(x, y), b = at(x + 1, y), c = at(x + 1, y + 1), d = at(x, y + 1);
      const Material& m = die(random) < 2 ? lamp : grey;
      if (die(random) == 0) {
        mesh.push_back({{a, b, c, d}, m});
        continue;
      }
      if (coin(random)) {
        mesh.push_back({{a, b, c}, m});
        mesh.push_back({{a, c, d}, die(random) == 0 ? lamp : m});
      } else {
        mesh.push_back({{b, c, d}, m});
        mesh.push_back({{d, a, b}, m});
      }
      if (die(random) == 0) mesh.push_back(mesh.back());  // a repeated triangle
    }
  std::shuffle(mesh.begin(), mesh.end(), random);
  return mesh;
}

TEST(CoplanarMerge, SameMergesAsTheScan) {
  std::mt19937 random(30);
  long total = 0;
  for (int round = 0; round < 40; ++round) {
    const std::vector<ImportedPatch> mesh = random_mesh(random, 2 + round % 12);
    long fast_pairs = 0, scan_pairs = 0;
    const std::vector<ImportedPatch> fast = merge_coplanar(mesh, fast_pairs);
    const std::vector<ImportedPatch> scan = scan_reference(mesh, scan_pairs);
    ASSERT_EQ(fast_pairs, scan_pairs) << round;
    ASSERT_EQ(fast.size(), scan.size()) << round;
    for (std::size_t k = 0; k < fast.size(); ++k) {
      ASSERT_EQ(fast[k].corners, scan[k].corners) << round << " " << k;
      ASSERT_EQ(fast[k].material.emission, scan[k].material.emission) << round << " " << k;
    }
    total += scan_pairs;
  }
  EXPECT_GT(total, 500);  // the meshes do merge (and not everything: lifted corners, lamps)
}

TEST(CoplanarMerge, HalvesOfASquareGiveBackTheSquare) {
  const Point a(0, 0, 0), b(1, 0, 0), c(1, 1, 0), d(0, 1, 0);
  long pairs = 0;
  const auto merged = merge_coplanar({{{a, b, c}, {}}, {{a, c, d}, {}}}, pairs);
  ASSERT_EQ(merged.size(), 1u);
  EXPECT_EQ(pairs, 1);
  EXPECT_EQ(merged[0].corners, (std::vector<Point>{a, b, c, d}));
  // An emitter and a grey triangle of the same reflectance are not one patch.
  Material lamp;
  lamp.emission = Point(1.0);
  pairs = 0;
  EXPECT_EQ(merge_coplanar({{{a, b, c}, {}}, {{a, c, d}, lamp}}, pairs).size(), 2u);
  EXPECT_EQ(pairs, 0);
}

}  // namespace
}  // namespace ncube::models

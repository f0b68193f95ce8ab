// FastOctree (host) walks as the octree walk of section 6 counts (visibility/octree.h): on
// every scene of scenes/, for the whole scene and for 7 shares, every mask and every counter
// (cells visited, ray-patch tests, plane crossings, rays) equals the literal walk's, point by
// point; and on the hand-worked cluster that reaches the depth limit.
#include "host/fast_octree.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <random>

#include "nodes/placement.h"
#include "octree_scenes.h"
#include "receiver_sample.h"
#include "scene_files.h"
#include "scene/scene_loader.h"

namespace ncube {
namespace {

// The variants of the slab tests this host runs.
std::vector<octree_lanes::Isa> host_variants() {
  std::vector<octree_lanes::Isa> variants;
  for (const auto isa : {octree_lanes::Isa::kSse2, octree_lanes::Isa::kAvx2, octree_lanes::Isa::kAvx512})
    if (octree_lanes::host_runs(isa)) variants.push_back(isa);
  return variants;
}

std::uint64_t compare(const Scene& scene, const std::vector<int>& set, int shooter_patch,
                      int points, unsigned seed, octree_lanes::Isa isa);

// Point by point: the fast walk against the literal one, with each variant; returns the cells
// the walks visited.
std::uint64_t compare(const Scene& scene, const std::vector<int>& set, int shooter_patch,
                      int points, unsigned seed) {
  std::uint64_t visited = 0;
  for (const auto isa : host_variants()) {
    SCOPED_TRACE(octree_lanes::isa_name(isa));
    visited = compare(scene, set, shooter_patch, points, seed, isa);
  }
  return visited;
}

std::uint64_t compare(const Scene& scene, const std::vector<int>& set, int shooter_patch,
                      int points, unsigned seed, octree_lanes::Isa isa) {
  const Octree literal(scene, set);
  const FastOctree fast(std::make_unique<const Octree>(scene, set), isa);
  std::mt19937 random(seed);
  const Shooter shooter = make_shooter(scene, shooter_patch, Rgb(1.0), 64);
  const ReceiverSample sample = sample_receivers(scene, shooter_patch, points, random);
  Octree::Scratch scratch = literal.make_scratch();
  std::uint64_t visited = 0;
  for (std::size_t k = 0; k < sample.points.size(); ++k) {
    WorkCounts expected, got;
    const PartMask want =
        literal.unblocked_parts(sample.points[k], sample.patches[k], shooter, expected, scratch);
    const PartMask have = fast.unblocked_parts(sample.points[k], sample.patches[k], shooter, got);
    EXPECT_EQ(have, want) << scene.name << ": shooter " << shooter_patch << ", point " << k;
    EXPECT_EQ(got, expected) << scene.name << ": shooter " << shooter_patch << ", point " << k;
    if (!(got == expected)) return visited;
    visited += got.octree_cells_visited;
  }
  return visited;
}

// Rays that start or end exactly on a corner of a cell's grown box, or run parallel to its
// faces (a zero component), as Octree::segment_meets_cell decides with equal parameters at
// an end or no interval on an axis: the hand-worked octrees of octree_scenes.h. Each ray is
// asked 11 times in one packet, so that it takes every lane of a group of 8 (and of a group
// left partly empty).
void compare_on_cell_corners(const Scene& scene, const OctreeParameters& parameters,
                             octree_lanes::Isa isa) {
  SCOPED_TRACE(octree_lanes::isa_name(isa));
  const std::vector<int> all = every_patch(scene);
  const Octree literal(scene, all, parameters);
  const FastOctree fast(std::make_unique<const Octree>(scene, all, parameters), isa);
  const std::vector<double>& bounds = literal.walk_bounds();
  std::vector<Vec3> directions;
  for (int x = -1; x <= 1; ++x)
    for (int y = -1; y <= 1; ++y)
      for (int z = -1; z <= 1; ++z)
        if (x || y || z) directions.emplace_back(x, y, z);
  Octree::Scratch scratch = literal.make_scratch();
  long rays = 0, blocked = 0;
  for (std::size_t cell = 0; 6 * cell < bounds.size(); ++cell)
    for (int corner = 0; corner < 8; ++corner) {
      const double* b = bounds.data() + 6 * cell;
      const Vec3 point(b[corner & 1 ? 3 : 0], b[corner & 2 ? 4 : 1], b[corner & 4 ? 5 : 2]);
      for (const Vec3& direction : directions)
        for (double length : {1e-6, 0.3, 5.0})
          for (int reverse = 0; reverse < 2; ++reverse) {
            Shooter shooter;
            shooter.patch = -1;
            shooter.part_count = 11;
            const Vec3 other = point + length * direction;
            for (int part = 0; part < shooter.part_count; ++part)
              shooter.targets[std::size_t(part)] = reverse ? point : other;
            const Vec3 from = reverse ? other : point;
            WorkCounts expected, got;
            const PartMask want = literal.unblocked_parts(from, -1, shooter, expected, scratch);
            const PartMask have = fast.unblocked_parts(from, -1, shooter, got);
            ASSERT_EQ(have, want) << scene.name << ": cell " << cell << ", corner " << corner;
            ASSERT_EQ(got, expected) << scene.name << ": cell " << cell << ", corner " << corner
                                     << ", direction " << direction.x << " " << direction.y
                                     << " " << direction.z << ", length " << length;
            ++rays;
            blocked += want == 0;
          }
    }
  EXPECT_GT(blocked, 0);
  EXPECT_LT(blocked, rays);
}

TEST(FastOctree, CountsAsTheWalkOnCellCornersAndFaces) {
  for (const auto isa : host_variants()) {
    compare_on_cell_corners(two_patch_scene(), OctreeParameters{1, 1}, isa);
    compare_on_cell_corners(two_patch_scene(), OctreeParameters{3, 1}, isa);
    compare_on_cell_corners(cluster_scene(9), OctreeParameters{}, isa);
  }
}

class FastOctreeOnScene : public ::testing::TestWithParam<std::string> {};

TEST_P(FastOctreeOnScene, CountsAsTheWalk) {
  const Scene scene = load_scene(std::string(NCUBE_SOURCE_DIR) + "/scenes/" + GetParam() + ".json");
  const int n = int(scene.patches.size());
  int emitter = 0;
  while (scene.patches[std::size_t(emitter)].emission == Rgb(0.0)) ++emitter;
  std::vector<int> all(static_cast<std::size_t>(n), 0);
  for (int p = 0; p < n; ++p) all[std::size_t(p)] = p;
  const int points = std::clamp(int(2e6 / n), 10, 300);
  std::uint64_t visited = compare(scene, all, emitter, points, 1);
  visited += compare(scene, all, (emitter + n / 3) % n, points, 2);
  for (int j = 0; j < 7; ++j) visited += compare(scene, visibility_share(scene, 7, j), emitter, points / 4 + 1, 3 + unsigned(j));
  // The walks must go deep enough to mean something: many more cells than rays.
  EXPECT_GT(visited, std::uint64_t(64) * std::uint64_t(points) * 4);
}

INSTANTIATE_TEST_SUITE_P(Scenes, FastOctreeOnScene, ::testing::ValuesIn(scene_files()),
                         scene_test_name);

}  // namespace
}  // namespace ncube

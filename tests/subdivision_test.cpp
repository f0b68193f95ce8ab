// Adaptive subdivision (paper section 4.1; radiosity/subdivision.h, the engine's subdivide):
// the criterion on corner radiosities worked out by hand, and one shot under a shadow edge
// that cuts recursively where the light changes and nowhere else.
#include <gtest/gtest.h>

#include "host/fast_occluders.h"

#include <numeric>

#include "radiosity/radiosity_engine.h"

namespace ncube {
namespace {

Patch strip(int nu) {  // 3 x 1 (x by y) on z = 0, facing +z
  Patch p;
  p.polygon = Polygon::quad(Vec3(0, 0, 0), Vec3(nu, 0, 0), Vec3(nu, 1, 0), Vec3(0, 1, 0));
  p.nu = nu;
  p.nv = 1;
  return p;
}

TEST(SubdivisionCriterion, AShadowEdgeIsCutAUniformlyLitElementIsNot) {
  // Radiosities 1, 1, 0: the light ends between elements 1 and 2. Corner luminances (Y of a
  // grey radiosity is the value): element 0: 1, 1 (x = 1: mean of 1 and 1) -> contrast 0;
  // element 1: 1 and 0.5 (x = 2: mean of 1 and 0) -> 1/3; element 2: 0.5 and 0 -> 1.
  const Patch p = strip(3);
  const PatchMesh mesh(p, {{0, 0, 0}, {0, 1, 0}, {0, 2, 0}});
  const std::vector<Rgb> b{Rgb(1.0), Rgb(1.0), Rgb(0.0)};
  EXPECT_DOUBLE_EQ(corner_contrast(mesh, b, 0), 0.0);
  EXPECT_DOUBLE_EQ(corner_contrast(mesh, b, 1), 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(corner_contrast(mesh, b, 2), 1.0);
  SubdivisionOptions o;
  o.contrast = 0.5;
  EXPECT_FALSE(should_cut(o, mesh, b, 0, {0, 0, 0}, 1.0));
  EXPECT_FALSE(should_cut(o, mesh, b, 1, {0, 1, 0}, 1.0));
  EXPECT_TRUE(should_cut(o, mesh, b, 2, {0, 2, 0}, 1.0));
  o.contrast = 0.3;
  EXPECT_TRUE(should_cut(o, mesh, b, 1, {0, 1, 0}, 1.0));
  // The limits: level and area.
  o.max_level = 0;
  EXPECT_FALSE(should_cut(o, mesh, b, 2, {0, 2, 0}, 1.0));
  o.max_level = 3;
  o.min_area = 0.3;  // children would be 0.25
  EXPECT_FALSE(should_cut(o, mesh, b, 2, {0, 2, 0}, 1.0));
}

// A small light over a floor strip, and a wide plate at height 1 over x >= 2: the plate's
// shadow on the floor begins at x = 3 (rays to the light at x = 1, height 2, cross height 1
// at x = (x_floor + 1) / 2).
Scene shadow_scene() {
  Scene s;
  Patch light;  // facing down, 0.2 x 0.2 at (1, 0.5, 2)
  light.polygon = Polygon::quad(Vec3(0.9, 0.4, 2), Vec3(0.9, 0.6, 2), Vec3(1.1, 0.6, 2), Vec3(1.1, 0.4, 2));
  light.emission = Rgb(10.0);
  Patch floor = strip(4);  // x in [0, 4], 4 x 1 elements
  floor.reflectance = Rgb(0.5);
  Patch plate;  // at z = 1 over x in [2, 10], facing down
  plate.polygon = Polygon::quad(Vec3(2, -5, 1), Vec3(2, 6, 1), Vec3(10, 6, 1), Vec3(10, -5, 1));
  s.patches = {light, floor, plate};
  s.build_elements();
  return s;
}

TEST(Subdivision, OneShotCutsRecursivelyAtTheShadowEdgeOnly) {
  const Scene s = shadow_scene();
  std::vector<int> all{0, 1, 2};
  RadiosityEngine engine(s, all);
  const FastOccluders occluders(s, all, RayTestPolicy::kTestAllPatches);
  ProgressiveOptions options;
  options.samples = 16;  // M = 16 (the paper's smaller M), as when it was the default
  options.max_iterations = 1;
  options.subdivision.enabled = true;
  options.subdivision.contrast = 0.5;
  options.subdivision.max_level = 3;
  const ProgressiveRun run = run_progressive(engine, occluders, options);
  ASSERT_EQ(run.shooters, std::vector<int>{0});
  const StoredPatch& floor = engine.store().patches()[1];
  int deepest = 0;
  for (const StoredElement& e : floor.elements) {
    deepest = std::max(deepest, e.cell.level);
    const double x0 = double(e.cell.i) / (4 << e.cell.level), x1 = double(e.cell.i + 1) / (4 << e.cell.level);
    // Under the light (x < 2) the floor is lit smoothly: nothing is cut there.
    if (4.0 * x1 <= 2.0) {
      EXPECT_EQ(e.cell.level, 0) << "cut at x " << 4 * x0;
    }
  }
  // The recursion went to the deepest level within the one shot, at the edge (x = 3).
  EXPECT_EQ(deepest, 3);
  bool deepest_at_edge = false;
  for (const StoredElement& e : floor.elements)
    if (e.cell.level == 3 && std::abs(e.centre.x - 3.0) < 0.5) deepest_at_edge = true;
  EXPECT_TRUE(deepest_at_edge);
  EXPECT_EQ(run.total.elements_created, std::uint64_t(floor.elements.size() - 4) / 3 * 4);
  EXPECT_EQ(run.elements.back(), engine.store().element_count());
  // A cut element's share of the shot was taken back and its children's added: the floor's
  // unshot radiosity is the reflected light of its elements as they are now.
  Rgb reflected(0.0);
  for (const StoredElement& e : floor.elements) reflected += e.shot_gain * (e.area / 4.0);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(floor.unshot[c], reflected[c], 1e-12 * reflected[c]);
  // Only the light shot, so every element's radiosity is its own gain of this shot: a
  // child's past light (its parent's, before the shot) is zero.
  for (const StoredElement& e : floor.elements) EXPECT_EQ(e.radiosity, e.shot_gain);
}

TEST(Subdivision, OffByDefaultAndBoundedByTheRoomGiven) {
  const Scene s = shadow_scene();
  std::vector<int> all{0, 1, 2};
  RadiosityEngine engine(s, all);
  const FastOccluders occluders(s, all, RayTestPolicy::kTestAllPatches);
  ProgressiveOptions options;
  options.samples = 16;  // M = 16 (the paper's smaller M), as when it was the default
  options.max_iterations = 1;
  run_progressive(engine, occluders, options);
  EXPECT_EQ(engine.store().element_count(), s.element_total());
  // Room for one cut only: one cut made, the rest wanted.
  WorkCounts counts;
  std::vector<ElementRef> floor;
  for (int k = 0; k < 4; ++k) floor.push_back({1, k});
  SubdivisionOptions o;
  o.enabled = true;
  bool out_of_room = false;
  const std::vector<ElementRef> children = engine.subdivide(floor, o, 5, out_of_room, counts);
  EXPECT_EQ(children.size(), 4u);
  EXPECT_TRUE(out_of_room);
  EXPECT_EQ(counts.subdivision_tests, 4u);
  EXPECT_EQ(counts.elements_created, 4u);
}

// A cut takes 4 element records, and the floor under the shadow edge wants 2 cuts: room for
// 3 records makes none, for exactly 4 one, for 7 still one, for exactly 8 both with nothing
// more wanted.
TEST(Subdivision, RoomForExactlyOneCutMakesIt) {
  const Scene s = shadow_scene();
  std::vector<int> all{0, 1, 2};
  const FastOccluders occluders(s, all, RayTestPolicy::kTestAllPatches);
  ProgressiveOptions options;
  options.samples = 16;
  options.max_iterations = 1;
  SubdivisionOptions o;
  o.enabled = true;
  std::vector<ElementRef> floor;
  for (int k = 0; k < 4; ++k) floor.push_back({1, k});
  const auto cut_with_room = [&](long room, bool& out_of_room) {
    RadiosityEngine engine(s, all);
    run_progressive(engine, occluders, options);
    WorkCounts counts;
    out_of_room = false;
    return engine.subdivide(floor, o, room, out_of_room, counts).size();
  };
  bool out_of_room = false;
  ASSERT_EQ(cut_with_room(1L << 40, out_of_room), 8u);  // 2 cuts, 4 children each
  ASSERT_FALSE(out_of_room);
  EXPECT_EQ(cut_with_room(3, out_of_room), 0u);
  EXPECT_TRUE(out_of_room);
  EXPECT_EQ(cut_with_room(4, out_of_room), 4u);
  EXPECT_TRUE(out_of_room);
  EXPECT_EQ(cut_with_room(7, out_of_room), 4u);
  EXPECT_TRUE(out_of_room);
  EXPECT_EQ(cut_with_room(8, out_of_room), 8u);
  EXPECT_FALSE(out_of_room);
}

}  // namespace
}  // namespace ncube

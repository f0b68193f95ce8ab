// The hemicube (src/radiosity/hemicube.h) against values worked out independently: the delta
// form factors' sum (the midpoint rule's error), the closed-form point-to-square form factor
// (Howell's catalogue, B-3: a plane element and a parallel rectangle with a corner on its
// normal), the exact contour integral for receivers that reach the side faces
// (radiosity/form_factor.h), occlusion, back faces, reciprocity, and the work of a one-cell
// case counted by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "hand_counted_scene.h"
#include "radiosity/form_factor.h"
#include "radiosity/hemicube.h"

namespace ncube {
namespace {

const Vec3 kEye(0.0), kUp(0, 0, 1), kTangent(1, 0, 0);

// A rectangle in the plane z = height over [x0, x1] x [y0, y1], facing down (to the eye).
Polygon ceiling(double x0, double x1, double y0, double y1, double height) {
  return Polygon::quad({x0, y0, height}, {x0, y1, height}, {x1, y1, height}, {x1, y0, height});
}

HemicubePolygon receiver(const Polygon& polygon) { return hemicube_polygon(polygon); }

// F(eye -> receivers[k]) from one hemicube at the origin looking up.
std::vector<double> point_form_factors(int n, const std::vector<HemicubePolygon>& receivers,
                                       const std::vector<HemicubePolygon>& occluders = {},
                                       WorkCounts* counts = nullptr) {
  WorkCounts ignored;
  std::vector<double> f(receivers.size(), 0.0);
  render_hemicube(kEye, kUp, kTangent, receivers, occluders, DeltaFormFactors(n), 1.0, f,
                  counts ? *counts : ignored);
  return f;
}

// Howell B-3: dA to a parallel a x b rectangle at distance c, the normal through a corner.
double corner_rectangle(double a, double b, double c) {
  const double x = a / c, y = b / c;
  return (x / std::sqrt(1 + x * x) * std::atan(y / std::sqrt(1 + x * x)) +
          y / std::sqrt(1 + y * y) * std::atan(x / std::sqrt(1 + y * y))) /
         (2 * M_PI);
}

TEST(Hemicube, DeltaFormFactorsSumToOneToTheMidpointRulesAccuracy) {
  // Not normalised: the sum is the midpoint rule's, short of 1 by O(1/N^2).
  const double error100 = 1.0 - DeltaFormFactors(100).sum();
  const double error200 = 1.0 - DeltaFormFactors(200).sum();
  EXPECT_GT(std::fabs(error100), 1e-6);
  EXPECT_LT(std::fabs(error100), 1e-4);
  EXPECT_NEAR(error100 / error200, 4.0, 0.05);  // second order
  // The whole top face is the point's form factor to the square [-1, 1]^2 at height 1.
  double top = 0.0;
  for (double f : DeltaFormFactors(400).top) top += f;
  EXPECT_NEAR(top, 4 * corner_rectangle(1, 1, 1), 2e-6);
}

TEST(Hemicube, ASquareOverTheEyeGetsItsCellsAndConvergesToTheClosedForm) {
  // Side 1 at height 1: on the top face it covers [-0.5, 0.5]^2, whole cells for N = 100.
  const std::vector<HemicubePolygon> square = {receiver(ceiling(-0.5, 0.5, -0.5, 0.5, 1.0))};
  double cells = 0.0;  // the cells whose centres lie in it, each dA / (pi (x^2 + y^2 + 1)^2)
  for (int j = 0; j < 100; ++j)
    for (int i = 0; i < 100; ++i) {
      const double x = -1 + (i + 0.5) * 0.02, y = -1 + (j + 0.5) * 0.02;
      if (std::fabs(x) < 0.5 && std::fabs(y) < 0.5)
        cells += 0.02 * 0.02 / (M_PI * std::pow(x * x + y * y + 1, 2));
    }
  EXPECT_NEAR(point_form_factors(100, square)[0], cells, 1e-15);
  const double exact = 4 * corner_rectangle(0.5, 0.5, 1.0);
  EXPECT_NEAR(exact, 0.239456, 1e-6);
  // N a multiple of 4: the square's edges fall on cell edges, and the error is the midpoint
  // rule's, O(1/N^2).
  double last = 1.0;
  for (const int n : {8, 20, 100, 400}) {
    const double error = std::fabs(point_form_factors(n, square)[0] - exact);
    EXPECT_LT(error, last / 4) << "N = " << n;
    last = error;
  }
  EXPECT_LT(last / exact, 1e-4);
  // N = 102: its edges fall on cell centres, which count as covered: one row and column too
  // many on every side (aliasing, kept).
  EXPECT_GT(point_form_factors(102, square)[0], exact * 1.01);
}

TEST(Hemicube, AReceiverOnTheSideFacesConvergesToTheContourIntegral) {
  // A wide ceiling reaching past the top face, and a wall beside the eye: both seen partly
  // or only on the side faces. Exact: the point-to-polygon contour integral.
  const Polygon wide = ceiling(0.5, 3.0, -0.5, 1.5, 1.0);
  const Polygon wall = Polygon::quad({2, -1, 0.1}, {2, -1, 1.2}, {2, 1.5, 1.2}, {2, 1.5, 0.1});
  ASSERT_LT(wall.normal().x, 0.0);  // facing the eye
  for (const Polygon& polygon : {wide, wall}) {
    const double exact = point_to_polygon_form_factor(kEye, kUp, polygon);
    const double coarse = point_form_factors(50, {receiver(polygon)})[0];
    const double fine = point_form_factors(800, {receiver(polygon)})[0];
    EXPECT_GT(exact, 0.01);
    EXPECT_NEAR(fine, exact, 2e-3 * exact);
    EXPECT_LT(std::fabs(fine - exact), std::fabs(coarse - exact) + 1e-12);
  }
}

TEST(Hemicube, TheNearestPolygonTakesTheCellAndBackFacesReceiveNothing) {
  const Polygon far = ceiling(-0.5, 0.5, -0.5, 0.5, 2.0);
  const Polygon near = ceiling(-1.0, 1.0, -1.0, 1.0, 1.0);
  // Blocked by an occluder, in either order of drawing; the occluder is not read out.
  EXPECT_EQ(point_form_factors(100, {receiver(far)}, {receiver(near)})[0], 0.0);
  const std::vector<double> both = point_form_factors(100, {receiver(near), receiver(far)});
  EXPECT_EQ(both[1], 0.0);
  EXPECT_EQ(both[0], point_form_factors(100, {receiver(near)})[0]);
  EXPECT_EQ(point_form_factors(100, {receiver(far), receiver(near)})[0], 0.0);
  // Half hidden: the hidden half's cells go to the occluder.
  const double alone = point_form_factors(100, {receiver(far)})[0];
  const double half = point_form_factors(100, {receiver(far)}, {receiver(ceiling(0.0, 1.0, -1.0, 1.0, 1.0))})[0];
  EXPECT_NEAR(half, alone / 2, 1e-12);
  // Seen from behind: it blocks the far square but gets nothing.
  const Polygon turned = Polygon::quad(near[3], near[2], near[1], near[0]);
  const std::vector<double> behind = point_form_factors(100, {receiver(turned), receiver(far)});
  EXPECT_EQ(behind[0], 0.0);
  EXPECT_EQ(behind[1], 0.0);
  // Below the eye's plane: nothing.
  EXPECT_EQ(point_form_factors(100, {receiver(ceiling(-1, 1, -1, 1, -1.0))})[0], 0.0);
}

// F(eye -> receivers[k]) with the back faces' choice.
std::vector<double> point_form_factors_with(HemicubeBackFaces back_faces, int n,
                                            const std::vector<HemicubePolygon>& receivers,
                                            const std::vector<HemicubePolygon>& occluders,
                                            WorkCounts& counts) {
  std::vector<double> f(receivers.size(), 0.0);
  render_hemicube(kEye, kUp, kTangent, receivers, occluders, DeltaFormFactors(n), 1.0, f, counts,
                  back_faces);
  return f;
}

TEST(Hemicube, GeometryBelowTheShootersPlaneReachesNoFace) {
  // What lies below the shooter's tangent plane is behind the shooter: its form factor is 0
  // (the integrand's cos at the shooter is negative there), and the side faces, which stop at
  // the eye's plane (z = 0), must give it no cell. Walls facing the eye beyond each of the
  // four side faces, from just under the plane down, a floor under the eye and a wall crossing
  // behind it: 0 on every face, and none hides a ceiling above the plane. The same walls lifted
  // above the plane get the point-to-polygon contour integral (they do reach the side faces).
  const double top = -1e-6, bottom = -1.5;
  const std::vector<Polygon> below = {
      Polygon::quad({2, -1, bottom}, {2, -1, top}, {2, 1.5, top}, {2, 1.5, bottom}),     // +x
      Polygon::quad({-2, 1.5, bottom}, {-2, 1.5, top}, {-2, -1, top}, {-2, -1, bottom}),  // -x
      Polygon::quad({-1, 2, bottom}, {1.5, 2, bottom}, {1.5, 2, top}, {-1, 2, top}),       // +y
      Polygon::quad({1.5, -2, bottom}, {-1, -2, bottom}, {-1, -2, top}, {1.5, -2, top}),   // -y
      Polygon::quad({-3, -3, -0.5}, {3, -3, -0.5}, {3, 3, -0.5}, {-3, 3, -0.5}),           // floor
      Polygon::quad({3, 0.5, bottom}, {3, 0.5, top}, {-3, 0.5, top}, {-3, 0.5, bottom})};  // crossing
  std::vector<Polygon> above;  // the four walls lifted to z from 1e-6 to 1.5
  for (std::size_t k = 0; k < 4; ++k) {
    Polygon lifted = below[k];
    for (Vec3& vertex : lifted.vertices) vertex.z += 1.5 + 2e-6;
    above.push_back(lifted);
  }
  const Polygon sky = ceiling(-3, 3, -3, 3, 1.0);
  for (const int n : {20, 100}) {
    for (std::size_t k = 0; k < below.size(); ++k) {
      ASSERT_LT(glm::dot(below[k].normal(), below[k][0] - kEye), 0.0) << k;  // facing the eye
      for (const HemicubeBackFaces back_faces :
           {HemicubeBackFaces::kBlock, HemicubeBackFaces::kPass}) {
        WorkCounts counts;
        EXPECT_EQ(point_form_factors_with(back_faces, n, {receiver(below[k])}, {}, counts)[0], 0.0)
            << "polygon " << k << ", N = " << n;
        // As an occluder it hides nothing above the plane: the ceiling gets all its cells.
        WorkCounts with, without;
        EXPECT_EQ(point_form_factors_with(back_faces, n, {receiver(sky)}, {receiver(below[k])}, with)[0],
                  point_form_factors_with(back_faces, n, {receiver(sky)}, {}, without)[0])
            << "polygon " << k << ", N = " << n;
      }
    }
  }
  for (const Polygon& wall : above) {
    const double exact = point_to_polygon_form_factor(kEye, kUp, wall);
    EXPECT_GT(exact, 0.01);
    WorkCounts counts;
    EXPECT_NEAR(point_form_factors_with(HemicubeBackFaces::kBlock, 400, {receiver(wall)}, {}, counts)[0],
                exact, 1e-2 * exact);
  }
  // A tilted shooter: the plane through the eye with normal (1, 1, 1) / sqrt 3. A triangle
  // wholly on its lower side (every vertex's height along the normal negative), spread round
  // the eye so that it projects towards several side faces, gets nothing.
  const Vec3 normal = glm::normalize(Vec3(1, 1, 1));
  const Vec3 tangent = glm::normalize(Vec3(1, -1, 0));
  const Polygon tilted = Polygon::triangle({3, -3, -0.2}, {-3, 3, -0.2}, {-2, -2, 1});
  for (int k = 0; k < 3; ++k) ASSERT_LT(glm::dot(tilted[k] - kEye, normal), 0.0);
  const Polygon facing = glm::dot(tilted.normal(), tilted[0] - kEye) < 0
                             ? tilted
                             : Polygon::triangle(tilted[2], tilted[1], tilted[0]);
  ASSERT_LT(glm::dot(facing.normal(), facing[0] - kEye), 0.0);
  std::vector<double> f(1, 0.0);
  WorkCounts counts;
  render_hemicube(kEye, normal, tangent, {receiver(facing)}, {}, DeltaFormFactors(100), 1.0, f,
                  counts);
  EXPECT_EQ(f[0], 0.0);
}

TEST(Hemicube, ABackFacingOccluderBlocksOrPassesAsChosen) {
  // A receiver seen through an occluder whose back faces the eye (the Cornell box's ceiling
  // over its light): block gives 0; pass gives the unoccluded cells exactly, which converge
  // to the closed form (Howell B-3) as without the occluder.
  const Polygon far = ceiling(-0.5, 0.5, -0.5, 0.5, 2.0);
  const Polygon near = ceiling(-1.0, 1.0, -1.0, 1.0, 1.0);
  const Polygon turned = Polygon::quad(near[3], near[2], near[1], near[0]);  // facing up
  ASSERT_GT(turned.normal().z, 0.0);
  const double exact = 4 * corner_rectangle(0.5, 0.5, 2.0);  // [-0.5, 0.5]^2 at 2
  EXPECT_NEAR(exact, point_to_polygon_form_factor(kEye, kUp, far), 1e-12);
  for (const int n : {200, 400}) {  // the square's edges on cell edges: the midpoint rule's error
    WorkCounts blocked_counts, passed_counts, alone_counts;
    const std::vector<double> blocked = point_form_factors_with(
        HemicubeBackFaces::kBlock, n, {receiver(far)}, {receiver(turned)}, blocked_counts);
    const std::vector<double> passed = point_form_factors_with(
        HemicubeBackFaces::kPass, n, {receiver(far)}, {receiver(turned)}, passed_counts);
    const std::vector<double> alone =
        point_form_factors_with(HemicubeBackFaces::kBlock, n, {receiver(far)}, {}, alone_counts);
    EXPECT_EQ(blocked[0], 0.0) << "N = " << n;
    EXPECT_EQ(passed[0], alone[0]) << "N = " << n;
    EXPECT_NEAR(passed[0], exact, 1e-4 * exact) << "N = " << n;
    // Culled after its facing test: set up (4 vertices, 1 plane), never clipped or scanned.
    WorkCounts culled = alone_counts;
    culled.hemicube_vertices_transformed += 4;
    culled.hemicube_polygons_set_up += 1;
    EXPECT_EQ(passed_counts, culled) << "N = " << n;
    EXPECT_GT(blocked_counts.hemicube_depth_tests, passed_counts.hemicube_depth_tests);
  }
  // The occluder's front blocks either way; a receiver seen from behind receives nothing
  // either way.
  for (const HemicubeBackFaces back_faces : {HemicubeBackFaces::kBlock, HemicubeBackFaces::kPass}) {
    WorkCounts counts;
    EXPECT_EQ(point_form_factors_with(back_faces, 100, {receiver(far)}, {receiver(near)}, counts)[0], 0.0);
    EXPECT_EQ(point_form_factors_with(back_faces, 100, {receiver(turned)}, {}, counts)[0], 0.0);
  }
  EXPECT_STREQ(hemicube_back_faces_name(HemicubeBackFaces::kBlock), "block");
  EXPECT_STREQ(hemicube_back_faces_name(HemicubeBackFaces::kPass), "pass");
  EXPECT_EQ(HemicubeOptions{}.back_faces, HemicubeBackFaces::kBlock);
}

TEST(Hemicube, AShooterJustAboveALightsBackPassesOnNothingUnlessBackFacesPass) {
  // The Cornell box's case in small: a ceiling (patch 0, 2 x 2 at y = 2, facing down), a
  // light just under its centre (patch 1, 1 x 1 at y = 1.99, facing down: its back to the
  // ceiling) and a floor (patch 2, 2 x 2 at y = 0, facing up). The ceiling's centre sees only
  // the light's back: with block the floor gets no form factor to the ceiling; with pass it
  // gets the unoccluded point-to-polygon factor, by reciprocity
  // F(floor -> ceiling) = F(centre -> floor) A_ceiling / A_floor, F(centre -> floor) =
  // 4 F(corner, 1 x 1 at 2) (Howell B-3).
  const Vec3 X(1, 0, 0), Z(0, 0, 1);
  Scene scene;
  scene.patches = {hand_counted_patch({-1, 2, -1}, 2.0 * X, 2.0 * Z, 0.0, 1, 1),
                   hand_counted_patch({-0.5, 1.99, -0.5}, X, Z, 1.0, 1, 1),
                   hand_counted_patch({-1, 0, -1}, 2.0 * Z, 2.0 * X, 0.0, 1, 1)};
  scene.build_elements();
  ASSERT_LT(scene.patches[0].normal.y, 0.0);
  ASSERT_LT(scene.patches[1].normal.y, 0.0);
  ASSERT_GT(scene.patches[2].normal.y, 0.0);
  const std::vector<HemicubePolygon> floor = {
      hemicube_polygon(scene, 2, scene.patches[2].polygon, scene.patches[2].area)};
  const std::vector<HemicubePolygon> light = {
      hemicube_polygon(scene, 1, scene.patches[1].polygon, scene.patches[1].area)};
  const double exact = 4 * corner_rectangle(1.0, 1.0, 2.0);
  HemicubeOptions options;
  options.resolution = 400;
  WorkCounts counts;
  EXPECT_EQ(hemicube_form_factors(scene, 0, floor, light, options, counts)[0], 0.0);
  options.back_faces = HemicubeBackFaces::kPass;
  const double passed = hemicube_form_factors(scene, 0, floor, light, options, counts)[0];
  EXPECT_NEAR(passed, exact, 1e-4 * exact);  // A_ceiling = A_floor
  EXPECT_EQ(passed, hemicube_form_factors(scene, 0, floor, {}, options, counts)[0]);
  // The light as a receiver of the ceiling's light: seen from behind, nothing either way.
  for (const HemicubeBackFaces back_faces : {HemicubeBackFaces::kBlock, HemicubeBackFaces::kPass}) {
    options.back_faces = back_faces;
    EXPECT_EQ(hemicube_form_factors(scene, 0, light, floor, options, counts)[0], 0.0);
  }
}

TEST(Hemicube, TheShootersFormFactorsFollowByReciprocityAndPlacement) {
  // The hand-counted scene: the light (patch 0, 1 x 1 at y = 2, facing down), the floor's
  // 5 elements under it (patch 1) and the table top (patch 2).
  const Scene scene = hand_counted_scene();
  std::vector<HemicubePolygon> floor;
  for (int e = scene.patches[1].first_element; e < scene.patches[1].first_element + 5; ++e)
    floor.push_back(hemicube_polygon(scene, 1, scene.elements[e].polygon, scene.elements[e].area));
  WorkCounts counts;
  HemicubeOptions options;
  const std::vector<double> f = hemicube_form_factors(scene, 0, floor, {}, options, counts);
  // One hemicube at the light's centre: F(element -> light) = F(centre -> element) A_light /
  // A_element, the point form factor read from the same cells.
  std::vector<double> point(floor.size(), 0.0);
  WorkCounts ignored;
  const Patch& light = scene.patches[0];
  render_hemicube(light.polygon.centroid(), light.normal, glm::normalize(light.polygon[1] - light.polygon[0]),
                  floor, {}, DeltaFormFactors(100), 1.0, point, ignored);
  for (std::size_t k = 0; k < floor.size(); ++k) {
    EXPECT_GT(f[k], 0.0);
    EXPECT_NEAR(f[k], point[k] * light.area / floor[k].area, 1e-15);
  }
  EXPECT_EQ(counts.hemicube_cells_read, 3u * 100u * 100u);  // one hemicube
  // The proximity error shows: the middle element's F(element -> light) is the light's
  // centre's view scaled, about A_light / (4 pi) at 2 units, 8 % above the exact
  // F(element centre -> light) of a 1 x 1 light (Howell B-3, 0.0735).
  const double exact = point_to_polygon_form_factor(scene.elements[scene.patches[1].first_element + 2].centre, scene.patches[1].normal,
                                                    light.polygon);
  EXPECT_NEAR(exact, 4 * corner_rectangle(0.5, 0.5, 2.0), 1e-12);
  EXPECT_GT(f[2], exact * 1.05);
  EXPECT_NEAR(f[2], light.area / (4 * M_PI), 0.01 * f[2]);
  // With the light cut into one element, placement "elements" is the centre's hemicube.
  options.placement = HemicubePlacement::kElements;
  WorkCounts element_counts;
  EXPECT_EQ(hemicube_form_factors(scene, 0, floor, {}, options, element_counts), f);
  EXPECT_EQ(element_counts, counts);
}

TEST(Hemicube, ReciprocityAboveOneIsCountedAndClampedOnlyWhenAsked) {
  // A 1 x 1 shooter on z = 0 facing up; a 0.02 x 0.02 receiver 0.01 above its centre facing
  // down (its point factor from the eye, a square of half-side 1 at distance 1 scaled, about
  // 0.55, times A_shooter / A_receiver = 2,500: far above 1), and a 1 x 1 receiver 10 above
  // (about 1/(100 pi) by reciprocity: far below 1).
  Scene scene;
  scene.name = "near receiver";
  Patch shooter;
  shooter.polygon = Polygon::quad({0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0});
  shooter.emission = Rgb(1.0);
  Patch near;
  near.polygon = ceiling(0.49, 0.51, 0.49, 0.51, 0.01);
  Patch far;
  far.polygon = ceiling(0.0, 1.0, 0.0, 1.0, 10.0);
  scene.patches = {shooter, near, far};
  scene.build_elements();
  const std::vector<HemicubePolygon> receivers = {receiver(scene.patches[1].polygon),
                                                  receiver(scene.patches[2].polygon)};
  HemicubeOptions options;
  WorkCounts counts;
  const std::vector<double> f = hemicube_form_factors(scene, 0, receivers, {}, options, counts);
  EXPECT_GT(f[0], 1000.0);
  EXPECT_LT(f[1], 0.01);
  EXPECT_EQ(counts.hemicube_reciprocal_above_one, 1u);
  // Clamped: the near receiver's factor is 1, the far one's unchanged, the count the same.
  options.reciprocity = HemicubeReciprocity::kClamp;
  WorkCounts clamped_counts;
  const std::vector<double> clamped = hemicube_form_factors(scene, 0, receivers, {}, options, clamped_counts);
  EXPECT_EQ(clamped[0], 1.0);
  EXPECT_EQ(clamped[1], f[1]);
  EXPECT_EQ(clamped_counts, counts);
  // Every eye counts for itself: with the shooter cut into 2 x 2 elements the near receiver
  // is near no eye (0.25 away), and its factor stays below 1.
  scene.patches[0].nu = scene.patches[0].nv = 2;
  scene.build_elements();
  options.placement = HemicubePlacement::kElements;
  options.reciprocity = HemicubeReciprocity::kAsComputed;
  WorkCounts element_counts;
  const std::vector<double> spread = hemicube_form_factors(scene, 0, receivers, {}, options, element_counts);
  EXPECT_LT(spread[0], 1.0);
  EXPECT_EQ(element_counts.hemicube_reciprocal_above_one, 0u);
}

TEST(Hemicube, WorkOfAOneCellCaseCountedByHand) {
  // N = 10 (cells 0.2 wide). A small ceiling at z = 1 over x in [0.05, 0.25], y in [0.27,
  // 0.47]: on the top face it covers one cell centre, (x, y) = (0.1, 0.3), cell (5, 6).
  // Clip tests, face by face (planes: d - a, d + a, d - b, d + b or b, near):
  //   top: all 4 vertices inside all 5 planes, 20 tests;
  //   +x (a = y, d = x): d - a = x - y < 0 for all, out at the first plane, 4 tests;
  //   -x (a = -y, d = -x): inside the first plane, out at the second (-x - y < 0), 8 tests;
  //   +y (a = x, d = y): inside the first two, out at the third (y - z < 0), 12 tests;
  //   -y (a = -x, d = -y): d - a = x - y < 0, out at the first plane, 4 tests. 48 in all.
  WorkCounts counts;
  const std::vector<double> f =
      point_form_factors(10, {receiver(ceiling(0.05, 0.25, 0.27, 0.47, 1.0))}, {}, &counts);
  WorkCounts expected;
  expected.hemicube_vertices_transformed = 4;
  expected.hemicube_polygons_set_up = 1;
  expected.hemicube_clip_tests = 48;
  expected.hemicube_vertices_projected = 4;
  expected.hemicube_polygons_scanned = 1;
  expected.hemicube_rows_scanned = 1;
  expected.hemicube_depth_tests = 1;
  expected.hemicube_cells_read = 10 * 10 + 4 * 10 * 5;
  EXPECT_EQ(counts, expected);
  EXPECT_NEAR(f[0], 0.2 * 0.2 / (M_PI * 1.1 * 1.1), 1e-15);
  EXPECT_EQ(hemicube_setup_work({10, HemicubePlacement::kCentre}).hemicube_delta_form_factors,
            150u);
}

TEST(Hemicube, WorkOfAReceiverAcrossTwoFacesCountedByHand) {
  // N = 10. A ceiling at z = 1 over x in [0.8, 1.2], y in [0.27, 0.47], across the top face's
  // edge x = z. Clip tests and cuts, face by face:
  //   top: d - a = 1 - x cuts two edges (4 tests, 2 cuts), the clipped x in [0.8, 1] is
  //        inside the other four planes (16 tests); one cell centre, (0.9, 0.3), cell (9, 6);
  //   +x (a = y, b = z, d = x): inside d - a and d + a (8), d - b = x - 1 cuts two edges (4
  //        tests, 2 cuts), inside b >= 0 and the near plane (8): 20 tests; the clipped x in
  //        [1, 1.2] projects to b / d in [0.83, 1], row 4 (z = 0.9), and at that row to a / d
  //        in [0.243, 0.423], column 6 (y = 0.3);
  //   -x: d - a = y - x < 0, out at once (4); +y: d - a = y - x < 0 (4); -y: inside
  //        d - a = x - y, out at d + a = -x - y (8). 56 tests, 4 cuts in all.
  WorkCounts counts;
  const std::vector<double> f =
      point_form_factors(10, {receiver(ceiling(0.8, 1.2, 0.27, 0.47, 1.0))}, {}, &counts);
  WorkCounts expected;
  expected.hemicube_vertices_transformed = 4;
  expected.hemicube_polygons_set_up = 1;
  expected.hemicube_clip_tests = 56;
  expected.hemicube_clip_cuts = 4;
  expected.hemicube_vertices_projected = 8;
  expected.hemicube_polygons_scanned = 2;
  expected.hemicube_rows_scanned = 2;
  expected.hemicube_depth_tests = 2;
  expected.hemicube_cells_read = 300;
  EXPECT_EQ(counts, expected);
  // Top cell (x, y) = (0.9, 0.3) and side cell (y, z) = (0.3, 0.9): r = 1.9 for both.
  EXPECT_NEAR(f[0], 0.04 / (M_PI * 1.9 * 1.9) + 0.9 * 0.04 / (M_PI * 1.9 * 1.9), 1e-15);
}

TEST(Hemicube, Resolutions) {
  EXPECT_TRUE(is_valid_hemicube_resolution(2));
  EXPECT_TRUE(is_valid_hemicube_resolution(100));
  EXPECT_TRUE(is_valid_hemicube_resolution(2000));
  EXPECT_FALSE(is_valid_hemicube_resolution(0));
  EXPECT_FALSE(is_valid_hemicube_resolution(99));
  EXPECT_FALSE(is_valid_hemicube_resolution(2002));
  EXPECT_EQ(HemicubeOptions{}.resolution, 100);
  EXPECT_EQ(HemicubeOptions{}.placement, HemicubePlacement::kCentre);
}

}  // namespace
}  // namespace ncube

// The accuracy reference (src/reference, docs/accuracy.md) against values worked out
// independently: Howell's catalogue closed forms, reciprocity, a closed enclosure, a blocked
// pair, a two-element system solved by hand and the error measure on hand-made solutions.
#include <cmath>
#include <gtest/gtest.h>

#include "reference/area_form_factors.h"
#include "reference/radiosity_solve.h"
#include "reference/solution_error.h"
#include "reference/stratified_points.h"

namespace ncube::reference {
namespace {

Scene scene_of(const std::vector<Polygon>& polygons, int n = 1) {
  Scene scene;
  scene.name = "test";
  for (const Polygon& polygon : polygons) {
    Patch p;
    p.polygon = polygon;
    p.reflectance = Rgb(0.5);
    p.nu = p.nv = n;
    scene.patches.push_back(p);
  }
  scene.build_elements();
  return scene;
}

double entry(const FormFactorRows& rows, int i, int j) {
  for (const FormFactorEntry& e : rows[std::size_t(i)])
    if (e.element == j) return e.value;
  return 0.0;
}

FormFactorRows form_factors(const Scene& scene, int side) {
  FormFactorOptions options;
  options.side = side;
  options.threads = 1;
  return area_form_factors(scene, options);
}

// Howell C-11: directly opposed parallel rectangles a x b at distance c (X = a/c, Y = b/c).
double opposed_rectangles(double x, double y) {
  const double x1 = std::sqrt(1 + x * x), y1 = std::sqrt(1 + y * y);
  return 2.0 / (M_PI * x * y) *
         (std::log(std::sqrt((1 + x * x) * (1 + y * y) / (1 + x * x + y * y))) +
          x * y1 * std::atan(x / y1) + y * x1 * std::atan(y / x1) - x * std::atan(x) -
          y * std::atan(y));
}

// Howell C-14: perpendicular rectangles with a common edge of length l, widths w (the
// emitting one, H = h/l, W = w/l); F from the W rectangle to the H one.
double perpendicular_rectangles(double h, double w) {
  const double hw = std::sqrt(h * h + w * w);
  const double a = (1 + w * w) * (1 + h * h) / (1 + w * w + h * h);
  const double b = w * w * (1 + w * w + h * h) / ((1 + w * w) * (w * w + h * h));
  const double c = h * h * (1 + h * h + w * w) / ((1 + h * h) * (h * h + w * w));
  return (w * std::atan(1 / w) + h * std::atan(1 / h) - hw * std::atan(1 / hw) +
          0.25 * std::log(a * std::pow(b, w * w) * std::pow(c, h * h))) /
         (M_PI * w);
}

// Unit squares: the floor z = 0 facing up, the ceiling z = 1 facing down, the wall x = 0
// facing +x.
const Polygon kFloor = Polygon::quad({0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0});
const Polygon kCeiling = Polygon::quad({0, 0, 1}, {0, 1, 1}, {1, 1, 1}, {1, 0, 1});
const Polygon kWall = Polygon::quad({0, 0, 0}, {0, 1, 0}, {0, 1, 1}, {0, 0, 1});

TEST(ReferenceFormFactors, HowellClosedFormsAreTheCatalogueValues) {
  EXPECT_NEAR(opposed_rectangles(1, 1), 0.1998, 5e-5);
  EXPECT_NEAR(perpendicular_rectangles(1, 1), 0.2000, 5e-5);
}

TEST(ReferenceFormFactors, StratifiedPointsIntegrateOverTrianglesAndQuads) {
  // The weighted mean of 1 and of the point is the area and the first moment (area times
  // centroid): the bilinear map of a triangle (collapsed at v2) or of a skew quad is not
  // area-uniform, and the Jacobian weights make up for it.
  const Polygon skew = Polygon::quad({0, 0, 0}, {2, 0, 0}, {1.5, 1, 0}, {0.2, 0.7, 0});
  const Polygon triangle = Polygon::triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  for (const Polygon& polygon : {skew, triangle}) {
    const auto points = stratified_points(polygon, 32, 7);
    double area = 0.0;
    Vec3 moment(0.0);
    for (const AreaSample& s : points) {
      area += s.weight;
      moment += s.weight * s.point;
    }
    area /= double(points.size());
    moment /= double(points.size());
    EXPECT_NEAR(area, polygon.area(), 2e-3 * polygon.area());
    const Vec3 expected = polygon.area() * polygon.centroid();
    EXPECT_NEAR(moment.x, expected.x, 2e-3 * polygon.area());
    EXPECT_NEAR(moment.y, expected.y, 2e-3 * polygon.area());
  }
}

TEST(ReferenceFormFactors, OpposedUnitSquaresConvergeToHowell) {
  const Scene scene = scene_of({kFloor, kCeiling});
  const double exact = opposed_rectangles(1, 1);
  const double coarse = std::fabs(entry(form_factors(scene, 2), 0, 1) - exact);
  const double fine = std::fabs(entry(form_factors(scene, 16), 0, 1) - exact);
  EXPECT_LT(fine, 2e-3 * exact);
  EXPECT_LT(fine, coarse);
}

TEST(ReferenceFormFactors, FarOpposedSquaresSampledAtBothEndsConvergeToHowell) {
  // 0.2 x 0.2 squares one unit apart: far (centres 1 apart, radii 0.14), so the kernel is
  // sampled at both ends, K point pairs.
  const Scene scene = scene_of({Polygon::quad({0, 0, 0}, {0.2, 0, 0}, {0.2, 0.2, 0}, {0, 0.2, 0}),
                                Polygon::quad({0, 0, 1}, {0, 0.2, 1}, {0.2, 0.2, 1}, {0.2, 0, 1})});
  const double exact = opposed_rectangles(0.2, 0.2);
  const double coarse = std::fabs(entry(form_factors(scene, 1), 0, 1) - exact);
  const double fine = std::fabs(entry(form_factors(scene, 16), 0, 1) - exact);
  EXPECT_LT(fine, 1e-3 * exact);
  EXPECT_LT(fine, coarse);
}

TEST(ReferenceFormFactors, PerpendicularUnitSquaresSharingAnEdgeConvergeToHowell) {
  const Scene scene = scene_of({kFloor, kWall});
  const double exact = perpendicular_rectangles(1, 1);
  const double coarse = std::fabs(entry(form_factors(scene, 2), 0, 1) - exact);
  const double fine = std::fabs(entry(form_factors(scene, 16), 0, 1) - exact);
  // The kernel is singular along the common edge: slower, still within 1 %.
  EXPECT_LT(fine, 1e-2 * exact);
  EXPECT_LT(fine, coarse);
}

TEST(ReferenceFormFactors, ReciprocityHoldsForElementsOfDifferentAreas) {
  // A 2 x 1 floor in 2 x 2 elements (0.5 each) and a unit wall in 3 x 3 (1/9 each).
  Scene scene;
  for (const auto& [polygon, n] :
       {std::pair{Polygon::quad({0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}), 2},
        std::pair{kWall, 3}}) {
    Patch p;
    p.polygon = polygon;
    p.nu = p.nv = n;
    scene.patches.push_back(p);
  }
  scene.build_elements();
  const FormFactorRows rows = form_factors(scene, 4);
  int checked = 0;
  for (int i = 0; i < int(scene.elements.size()); ++i)
    for (const FormFactorEntry& e : rows[std::size_t(i)]) {
      const double forward = e.value * scene.elements[std::size_t(i)].area;
      const double back = entry(rows, e.element, i) * scene.elements[std::size_t(e.element)].area;
      EXPECT_NEAR(forward, back, 1e-12 * forward);
      ++checked;
    }
  EXPECT_EQ(checked, 2 * 4 * 9);  // every floor element sees every wall element
}

TEST(ReferenceFormFactors, RowsOfAClosedCubeSumToOne) {
  // The unit cube's six faces facing inward, 2 x 2 elements each.
  const std::vector<Polygon> faces = {
      kFloor, kCeiling, kWall,
      Polygon::quad({1, 0, 0}, {1, 0, 1}, {1, 1, 1}, {1, 1, 0}),   // x = 1, facing -x
      Polygon::quad({0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}),   // y = 0, facing +y
      Polygon::quad({0, 1, 0}, {1, 1, 0}, {1, 1, 1}, {0, 1, 1})};  // y = 1, facing -y
  const Scene scene = scene_of(faces, 2);
  for (const Patch& p : scene.patches)  // every face faces the cube's centre
    ASSERT_GT(glm::dot(p.normal, Vec3(0.5) - p.polygon.centroid()), 0.0);
  // The largest |row sum - 1| falls as K grows: sampling error, not a bias.
  auto largest_deviation = [&](int side) {
    double largest = 0.0;
    for (const auto& row : form_factors(scene, side)) {
      double sum = 0.0;
      for (const FormFactorEntry& e : row) sum += e.value;
      largest = std::max(largest, std::fabs(sum - 1.0));
    }
    return largest;
  };
  const double coarse = largest_deviation(4), fine = largest_deviation(16);
  std::printf("largest |row sum - 1|: %.2e at K = 16, %.2e at K = 256\n", coarse, fine);
  EXPECT_LT(fine, 5e-3);
  EXPECT_LT(fine, coarse);
}

TEST(ReferenceFormFactors, ABlockerBetweenTwoSquaresHidesThemFromEachOther) {
  // A larger square at z = 0.5 between the floor and the ceiling (facing down).
  const Polygon blocker = Polygon::quad({-1, -1, 0.5}, {-1, 2, 0.5}, {2, 2, 0.5}, {2, -1, 0.5});
  const FormFactorRows rows = form_factors(scene_of({kFloor, kCeiling, blocker}), 4);
  EXPECT_EQ(entry(rows, 0, 1), 0.0);
  EXPECT_EQ(entry(rows, 1, 0), 0.0);
  EXPECT_GT(entry(rows, 0, 2), 0.5);  // the floor sees the blocker instead
}

TEST(ReferenceFormFactors, SolveMatchesTheTwoElementSystemByHand) {
  // B0 = E0 + r0 F01 B1, B1 = E1 + r1 F10 B0 (one channel per colour):
  // B0 = (E0 + r0 F01 E1) / (1 - r0 r1 F01 F10).
  Scene scene = scene_of({kFloor, kCeiling});
  scene.patches[0].emission = Rgb(1.0, 2.0, 0.0);
  scene.patches[0].reflectance = Rgb(0.3, 0.6, 0.9);
  scene.patches[1].emission = Rgb(0.0, 0.5, 4.0);
  scene.patches[1].reflectance = Rgb(0.8, 0.2, 0.5);
  const double f01 = 0.4, f10 = 0.7;
  const FormFactorRows rows = {{{1, f01}}, {{0, f10}}};
  const std::vector<Rgb> b = solve_radiosity(scene, rows);
  for (int c = 0; c < 3; ++c) {
    const double e0 = scene.patches[0].emission[c], e1 = scene.patches[1].emission[c];
    const double r0 = scene.patches[0].reflectance[c], r1 = scene.patches[1].reflectance[c];
    const double b0 = (e0 + r0 * f01 * e1) / (1 - r0 * r1 * f01 * f10);
    const double b1 = e1 + r1 * f10 * b0;
    EXPECT_NEAR(b[0][c], b0, 1e-12) << "channel " << c;
    EXPECT_NEAR(b[1][c], b1, 1e-12) << "channel " << c;
  }
}

TEST(ReferenceFormFactors, ErrorMeasureOnHandMadeSolutions) {
  // Patch 0: one element of area 1; patch 1: two elements of area 1/2 each (a unit square
  // in 2 x 1). Grey radiosities, so luminance = the value (weights sum to 1).
  Scene scene = scene_of({kFloor, kCeiling});
  scene.patches[1].nu = 2;
  scene.build_elements();
  ASSERT_EQ(scene.elements.size(), 3u);
  const std::vector<Rgb> reference = {Rgb(1.0), Rgb(2.0), Rgb(4.0)};
  const std::vector<Rgb> solution = {Rgb(1.5), Rgb(3.0), Rgb(3.0)};
  const SolutionError error = solution_error(scene, solution, reference);
  // Relative errors 0.5, 0.5, -0.25 on areas 1, 1/2, 1/2: sum A r^2 = 0.25 + 0.125 +
  // 0.03125 over an area of 2.
  EXPECT_NEAR(error.element_rms, std::sqrt(0.40625 / 2.0), 1e-14);
  // Patches: reference 1 and 3, solution 1.5 and 3: relative errors 0.5 and 0.
  EXPECT_NEAR(error.patch_max, 0.5, 1e-14);
  EXPECT_EQ(error.worst_patch, 0);
  EXPECT_NEAR(error.patch_rms, std::sqrt(0.25 / 2.0), 1e-14);
}

}  // namespace
}  // namespace ncube::reference

#include "radiosity/form_factor.h"

#include <cmath>
#include <gtest/gtest.h>
#include <iostream>
#include <random>

namespace ncube {
namespace {

// Mean of F(dA -> emitter) over an n x n midpoint grid of a unit-square receiver spanned by
// origin + s * u + t * v: the patch-to-patch form factor F(receiver -> emitter).
double area_form_factor(const Vec3& origin, const Vec3& u, const Vec3& v, const Vec3& normal,
                        const Polygon& emitter, int n) {
  double sum = 0.0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      sum += point_to_polygon_form_factor(origin + (i + 0.5) / n * u + (j + 0.5) / n * v, normal,
                                          emitter);
  return sum / (n * n);
}

TEST(FormFactor, OpposedUnitSquaresAtDistanceOneMatchHowellCatalogue) {
  // Howell catalogue C-11: two directly opposed unit squares one unit apart, F = 0.1998.
  const Polygon emitter = Polygon::quad({0, 0, 1}, {0, 1, 1}, {1, 1, 1}, {1, 0, 1});
  const double f = area_form_factor({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, emitter, 40);
  EXPECT_NEAR(f, 0.1998, 0.01 * 0.1998);
}

TEST(FormFactor, PerpendicularUnitSquaresSharingAnEdgeMatchHowellCatalogue) {
  // Howell catalogue C-14: perpendicular unit squares with a common edge, F = 0.2000.
  const Polygon wall = Polygon::quad({0, 0, 0}, {0, 0, 1}, {0, 1, 1}, {0, 1, 0});  // x = 0
  const double f = area_form_factor({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, wall, 200);
  EXPECT_NEAR(f, 0.2000, 0.01 * 0.2000);
}

TEST(FormFactor, PointBelowCornerOfParallelRectangleMatchesClosedForm) {
  // Differential area below a corner of a parallel a x b rectangle at height c:
  // F = 1/(2 pi) [A/sqrt(1+A^2) atan(B/sqrt(1+A^2)) + B/sqrt(1+B^2) atan(A/sqrt(1+B^2))].
  const double a = 2.0, b = 0.7, c = 1.3;
  const double A = a / c, B = b / c;
  const double expected = (A / std::sqrt(1 + A * A) * std::atan(B / std::sqrt(1 + A * A)) +
                           B / std::sqrt(1 + B * B) * std::atan(A / std::sqrt(1 + B * B))) /
                          (2 * M_PI);
  const Polygon rect = Polygon::quad({0, 0, c}, {0, b, c}, {a, b, c}, {a, 0, c});
  EXPECT_NEAR(point_to_polygon_form_factor({0, 0, 0}, {0, 0, 1}, rect), expected, 1e-12);
}

TEST(FormFactor, DoesNotDependOnVertexOrderOrPolygonOrientation) {
  const Polygon ccw = Polygon::quad({0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1});
  const Polygon cw = Polygon::quad({0, 0, 1}, {0, 1, 1}, {1, 1, 1}, {1, 0, 1});
  const Vec3 p(0.3, 0.2, 0), n(0, 0, 1);
  EXPECT_NEAR(point_to_polygon_form_factor(p, n, ccw), point_to_polygon_form_factor(p, n, cw),
              1e-15);
}

TEST(FormFactor, OnlyThePartInFrontOfTheReceiverCounts) {
  // A vertical square straddling the receiver's plane sees the same as its upper half.
  const Polygon straddling = Polygon::quad({1, -1, -1}, {1, 1, -1}, {1, 1, 1}, {1, -1, 1});
  const Polygon upper = Polygon::quad({1, -1, 0}, {1, 1, 0}, {1, 1, 1}, {1, -1, 1});
  const Vec3 p(0, 0, 0), n(0, 0, 1);
  EXPECT_GT(point_to_polygon_form_factor(p, n, upper), 0.05);
  EXPECT_NEAR(point_to_polygon_form_factor(p, n, straddling),
              point_to_polygon_form_factor(p, n, upper), 1e-14);
  const Polygon behind = Polygon::quad({1, -1, -2}, {1, 1, -2}, {1, 1, -1}, {1, -1, -1});
  EXPECT_EQ(point_to_polygon_form_factor(p, n, behind), 0.0);
}

TEST(FormFactor, HemisphereOfLargePolygonApproachesOne) {
  // A huge parallel square just above the point fills the hemisphere: F -> 1.
  const double s = 1e4;
  const Polygon sky = Polygon::quad({-s, -s, 1}, {s, -s, 1}, {s, s, 1}, {-s, s, 1});
  EXPECT_NEAR(point_to_polygon_form_factor({0, 0, 0}, {0, 0, 1}, sky), 1.0, 1e-3);
}


}  // namespace
}  // namespace ncube

namespace ncube {
namespace {

// The outline sum of the visible parts equals the sum of the parts' own contour integrals
// (the reference: point_to_polygon_form_factor part by part) to 1e-12 relative, for quad and
// triangle shooters, random masks, receivers in front of the shooter facing every way
// (clipped and unclipped parts).
TEST(FormFactor, VisiblePartsSumEqualsThePartByPartSum) {
  std::mt19937 random(17);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Scene scene;
  Patch quad, triangle;
  quad.polygon = Polygon::quad({0, 2, 0}, {0.8, 2, 0.1}, {0.9, 2.1, 1.0}, {-0.1, 2, 0.9});
  triangle.polygon = Polygon::triangle({0, 2, 0}, {1, 2.2, 0}, {0.4, 2.1, 1});
  quad.reflectance = triangle.reflectance = Rgb(0.5);
  scene.patches = {quad, triangle};
  scene.build_elements();
  int unclipped = 0, clipped = 0;
  double largest_error = 0.0;
  for (int patch = 0; patch < 2; ++patch)
    for (int samples : {1, 4, 16, 64}) {
      const Shooter shooter = make_shooter(scene, patch, Rgb(1.0), samples);
      for (int trial = 0; trial < 400; ++trial) {
        Vec3 point(uniform(random), uniform(random), uniform(random));
        if (glm::dot(shooter.normal, point - shooter.polygon[0]) <= 0.0)
          point -= 2.0 * glm::dot(shooter.normal, point - shooter.polygon[0]) * shooter.normal;
        Vec3 normal = glm::normalize(Vec3(uniform(random), uniform(random), uniform(random)));
        if (trial % 2 == 0 && glm::dot(normal, shooter.targets[0] - point) < 0.0) normal = -normal;
        PartMask mask = std::uniform_int_distribution<PartMask>()(random) & shooter.all_parts();
        if (trial % 5 == 0) mask = shooter.all_parts();
        double expected = 0.0;
        bool any_clipped = false;
        for (int part = 0; part < shooter.part_count; ++part) {
          for (int v = 0; v < shooter.parts[part].count; ++v)
            any_clipped = any_clipped || glm::dot(normal, shooter.parts[part][v] - point) < 0.0;
          if (mask >> part & 1)
            expected += point_to_polygon_form_factor(point, normal, shooter.parts[part]);
        }
        (any_clipped ? clipped : unclipped)++;
        const double got = visible_parts_form_factor(point, normal, shooter, mask);
        ASSERT_NEAR(got, expected, 1e-12 * expected + 1e-300)
            << "patch " << patch << " M " << samples << " trial " << trial;
        if (expected > 0.0) largest_error = std::max(largest_error, std::fabs(got - expected) / expected);
      }
    }
  EXPECT_GT(unclipped, 500);  // both ways of summing are exercised
  EXPECT_GT(clipped, 500);
  std::cout << "largest relative difference " << largest_error << "\n";
}

// The host work counter form_factor_edge_terms (work_counts.h), worked by hand on an 8 x 8
// shooter (M = 64): seen from in front, every part visible is the square's outline (4 x 8
// edges), one part alone its 4 edges, none
// nothing; from a point whose tangent plane cuts the shooter (clipping), each visible part's
// clipped polygon (a part wholly in front keeps its 4 edges).
TEST(FormFactor, EdgeTermsAreTheContourOrTheClippedPartsHandCounted) {
  Scene scene;
  Patch square;
  square.polygon = Polygon::quad({0, 0, 0}, {8, 0, 0}, {8, 8, 0}, {0, 8, 0});  // faces +z
  square.reflectance = Rgb(0.5);
  scene.patches = {square};
  scene.build_elements();
  const Shooter shooter = make_shooter(scene, 0, Rgb(1.0), 64);
  ASSERT_EQ(shooter.side, 8);
  const Vec3 above(4, 4, 3), up(0, 0, -1);  // looking down at the shooter: no clipping
  EXPECT_EQ(form_factor_edge_terms(above, up, shooter, shooter.all_parts()), 32u);
  EXPECT_EQ(form_factor_edge_terms(above, up, shooter, PartMask(1) << 27), 4u);
  EXPECT_EQ(form_factor_edge_terms(above, up, shooter, 0), 0u);
  PartMask checkerboard = 0;
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 8; ++i)
      if ((i + j) % 2 == 0) checkerboard |= PartMask(1) << (j * 8 + i);
  // The checkerboard: every inner edge (2 x 8 x 7) and the outline's edges of visible parts (16).
  EXPECT_EQ(form_factor_edge_terms(above, up, shooter, checkerboard), 128u);
  // A receiver at x = 3.5 facing -x: its tangent plane cuts the parts of column 3 in half
  // (each clipped to a quad, 4 edges); columns 0-2 lie wholly in front (4 edges each), 4-7
  // behind (clipped away: none).
  const Vec3 side(3.5, 4, 1), minus_x(-1, 0, 0);
  EXPECT_EQ(form_factor_edge_terms(side, minus_x, shooter, shooter.all_parts()), 32u * 4u);
  EXPECT_EQ(form_factor_edge_terms(side, minus_x, shooter, PartMask(1) << 4), 0u);  // (4, 0)
  EXPECT_EQ(form_factor_edge_terms(side, minus_x, shooter, PartMask(1) << 3), 4u);  // (3, 0)
}

}  // namespace
}  // namespace ncube

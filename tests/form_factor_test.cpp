#include "radiosity/form_factor.h"

#include <cmath>
#include <gtest/gtest.h>

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

// The accuracy reference (src/reference, docs/accuracy.md) against values worked out
// independently: Howell's catalogue closed forms, reciprocity, a closed enclosure, a blocked
// pair, a two-element system solved by hand and the error measure on hand-made solutions.
#include <algorithm>
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

double entry(const FormFactors& factors, int i, int j) {
  for (const FormFactorEntry& e : factors.row(i))
    if (e.element == j) return e.value;
  return 0.0;
}

FormFactors form_factors(const Scene& scene, int side) {
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
  const FormFactors rows = form_factors(scene, 4);
  int checked = 0;
  for (int i = 0; i < int(scene.elements.size()); ++i)
    for (const FormFactorEntry& e : rows.row(i)) {
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
    const FormFactors factors = form_factors(scene, side);
    for (int i = 0; i < factors.size(); ++i) {
      double sum = 0.0;
      for (const FormFactorEntry& e : factors.row(i)) sum += e.value;
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
  const FormFactors rows = form_factors(scene_of({kFloor, kCeiling, blocker}), 4);
  EXPECT_EQ(entry(rows, 0, 1), 0.0);
  EXPECT_EQ(entry(rows, 1, 0), 0.0);
  EXPECT_GT(entry(rows, 0, 2), 0.5);  // the floor sees the blocker instead
}

// Straddling pairs (issue 38): only the front of an element sends and receives. A floor
// square z = 0 (facing up, x and y in [x0, x0 + a]) and a wall square in the plane x = c
// facing -x, beyond the floor's side in y (from y0 + g a) and crossing the floor's plane
// (z in [-a/2, a/2]). The floor's part with x > c is behind the wall's plane and the wall's
// part below z = 0 is behind the floor's: neither may send to or receive from the other.
// The exact value, worked out here without the reference's code: the one-sided
// point-to-polygon factor of each floor point to the wall clipped to the floor point's front
// half-space (z > 0), as a Gauss-Legendre product quadrature over the wall's front part,
// integrated over the floor's front part (x < c) the same way. No edge is shared and the
// two never touch, so the integrand is smooth on both parts.
struct StraddlingPair {
  double x0, y0, a, c, g;
  Polygon floor() const {
    return Polygon::quad({x0, y0, 0}, {x0 + a, y0, 0}, {x0 + a, y0 + a, 0}, {x0, y0 + a, 0});
  }
  Polygon wall() const {  // facing -x (checked below)
    const double yw = y0 + g * a;
    return Polygon::quad({c, yw, -a / 2}, {c, yw, a / 2}, {c, yw + a, a / 2}, {c, yw + a, -a / 2});
  }
  // A_floor F_floor,wall: integral over the floor's front part of the one-sided point factor.
  double exchange() const {
    // 24-point Gauss-Legendre nodes and weights on [-1, 1], from the Newton iteration on
    // the Legendre polynomial (no table to copy wrong).
    constexpr int n = 24;
    double node[n], weight[n];
    for (int i = 0; i < n; ++i) {
      double t = std::cos(M_PI * (i + 0.75) / (n + 0.5)), dp = 0.0;
      for (int it = 0; it < 100; ++it) {
        double p0 = 1.0, p1 = t;
        for (int k = 2; k <= n; ++k) {
          const double p2 = ((2 * k - 1) * t * p1 - (k - 1) * p0) / k;
          p0 = p1;
          p1 = p2;
        }
        dp = n * (t * p1 - p0) / (t * t - 1.0);
        t -= p1 / dp;
      }
      node[i] = t;
      weight[i] = 2.0 / ((1.0 - t * t) * dp * dp);
    }
    auto integrate = [&](double lo, double hi, auto&& f) {
      double sum = 0.0;
      for (int i = 0; i < n; ++i) sum += weight[i] * f(0.5 * (lo + hi) + 0.5 * (hi - lo) * node[i]);
      return 0.5 * (hi - lo) * sum;
    };
    const double yw = y0 + g * a;
    // The wall's front part for a floor point: z > 0; the floor's front part for the wall: x < c.
    return integrate(x0, std::min(c, x0 + a), [&](double x) {
      return integrate(y0, y0 + a, [&](double y) {
        return integrate(yw, yw + a, [&](double wy) {
          return integrate(0.0, a / 2, [&](double wz) {
            const Vec3 d(c - x, wy - y, wz);  // floor point to wall point
            const double r2 = glm::dot(d, d);
            return d.z * d.x / (M_PI * r2 * r2);  // cos at the floor (+z) times cos at the wall (-x)
          });
        });
      });
    });
  }
};

void expect_straddling_pair_exact(const StraddlingPair& pair, bool near) {
  const Scene scene = scene_of({pair.floor(), pair.wall()});
  ASSERT_GT(glm::dot(scene.patches[1].normal, Vec3(-1, 0, 0)), 0.99);  // the wall faces -x
  // The branch the test is about (area_form_factors.h: near when the centres are closer
  // than kNearFactor times the sum of the radii).
  const double gap = glm::length(scene.elements[1].centre - scene.elements[0].centre);
  const double radii = std::sqrt(0.5) * pair.a * 2;
  ASSERT_EQ(gap < FormFactorOptions::kNearFactor * radii, near);
  const double exact = pair.exchange() / (pair.a * pair.a);
  // The mean over 16 seeds of K = 256 (one seed's sampling error: about 3 % far). Measured
  // with the line that skips the points behind removed (issue 38's bug): the near value
  // 52 % too high; with the far kernel two-sided and its rays not cast: the far value 2.9
  // times the exact (the far branch is one-sided twice over: the kernel's cosines, and a
  // ray from behind an element meets the element itself, its end being lifted to the front).
  double forward = 0.0, back = 0.0;
  constexpr int seeds = 16;
  for (int seed = 0; seed < seeds; ++seed) {
    FormFactorOptions options;
    options.side = 16;
    options.threads = 1;
    options.seed = 1994 + std::uint64_t(seed);
    const FormFactors rows = area_form_factors(scene, options);
    forward += entry(rows, 0, 1) / seeds;
    back += entry(rows, 1, 0) / seeds;
  }
  std::printf("F_floor,wall: %.7f, exact %.7f\n", forward, exact);
  const double tolerance = near ? 1e-2 : 3e-2;
  EXPECT_NEAR(forward, exact, tolerance * exact);
  EXPECT_NEAR(back, exact, tolerance * exact);  // same areas: F_wall,floor alike
}

TEST(ReferenceFormFactors, NearPairStraddlingEachOthersPlaneExchangesOnlyFrontToFront) {
  // A unit floor and a unit wall at x = 0.6 beyond its far side (y from 1.5): centres 1.5
  // apart against radii of 0.71 each, near. 40 % of the floor lies behind the wall's plane,
  // half the wall below the floor's.
  expect_straddling_pair_exact({0.0, 0.0, 1.0, 0.6, 1.5}, true);
}

TEST(ReferenceFormFactors, FarPairStraddlingEachOthersPlaneExchangesOnlyFrontToFront) {
  // 0.2 x 0.2 squares, the wall at x = 0.12 and from y = 0.7: centres 0.7 apart against
  // radii of 0.14 each, far: the kernel sampled at both ends.
  expect_straddling_pair_exact({0.0, 0.0, 0.2, 0.12, 3.5}, false);
}

// Gauss-Legendre nodes and weights on [0, 1] (Newton on the Legendre polynomial).
std::vector<std::pair<double, double>> gauss_legendre(int n) {
  std::vector<std::pair<double, double>> rule;
  for (int i = 0; i < n; ++i) {
    double t = std::cos(M_PI * (i + 0.75) / (n + 0.5)), dp = 0.0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0, p1 = t;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2 * k - 1) * t * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (t * p1 - p0) / (t * t - 1.0);
      t -= p1 / dp;
    }
    rule.push_back({0.5 * (t + 1.0), 1.0 / ((1.0 - t * t) * dp * dp)});
  }
  return rule;
}

// The test's own one-sided point-to-rectangle factor (Lambert's contour integral over the
// corners, which must all lie on or in front of the point's plane and face the point):
// 1/(2 pi) sum over edges of the angle they subtend times the normal's share of their plane's.
double point_factor(const Vec3& x, const Vec3& n, const std::vector<Vec3>& corners) {
  double sum = 0.0;
  for (std::size_t k = 0; k < corners.size(); ++k) {
    const Vec3 a = glm::normalize(corners[k] - x), b = glm::normalize(corners[(k + 1) % corners.size()] - x);
    const Vec3 g = glm::cross(a, b);
    if (glm::length(g) < 1e-300) continue;
    sum += std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0)) * glm::dot(glm::normalize(g), n);
  }
  return std::fabs(sum) / (2.0 * M_PI);
}

// F from the rectangle origin + s u + t v (s, t in [0, 1], normal n) to `corners`: the
// point factor averaged over it by an n x n Gauss-Legendre product rule.
double rectangle_factor(const Vec3& origin, const Vec3& u, const Vec3& v, const Vec3& n,
                        const std::vector<Vec3>& corners) {
  double sum = 0.0;
  for (const auto& [s, ws] : gauss_legendre(48))
    for (const auto& [t, wt] : gauss_legendre(48)) sum += ws * wt * point_factor(origin + s * u + t * v, n, corners);
  return sum;
}

TEST(ReferenceFormFactors, AnElementHalfInsideABottomlessBoxSendsItsOpenPartsRadiosity) {
  // A 2 x 1 floor (one element, rho 0.8) whose half x > 1 is inside a bottomless box 0.001
  // high (rho 0), under a 2 x 1 emitter at z = 1 (E = 1, facing down) and beside a unit wall
  // at x = 0 (rho 0.5, facing +x). The enclosed half sees only the box's backs: it receives
  // nothing and sends nothing. The open half's radiosity B_o is what the floor sends, so the
  // wall gets rho_w F_w,o B_o from it, not the element's mean B_o / 2 (which halved it: about
  // 8 % of the wall). Exact, with the test's own factors (the box, 0.001 high, hides the
  // emitter from a share of about 1e-4 of the open half only):
  //   B_o = 0.8 (F_o,c + F_o,w B_w),  B_w = 0.5 (F_w,c + F_w,o B_o),  F_w,o = F_o,w,
  // the floor element's mean B_o / 2, the wall's B_w.
  const double h = 0.001;
  Scene scene;
  const auto add = [&](const Polygon& polygon, double rho, double emission) {
    Patch p;
    p.polygon = polygon;
    p.reflectance = Rgb(rho);
    p.emission = Rgb(emission);
    scene.patches.push_back(p);
  };
  add(Polygon::quad({0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}), 0.8, 0.0);  // the floor
  add(Polygon::quad({0, 0, 0}, {0, 1, 0}, {0, 1, 1}, {0, 0, 1}), 0.5, 0.0);  // the wall
  add(Polygon::quad({0, 0, 1}, {0, 1, 1}, {2, 1, 1}, {2, 0, 1}), 0.0, 1.0);  // the emitter
  add(Polygon::quad({1, 0, h}, {2, 0, h}, {2, 1, h}, {1, 1, h}), 0.0, 0.0);  // the box: top,
  add(Polygon::quad({1, 0, 0}, {1, 0, h}, {1, 1, h}, {1, 1, 0}), 0.0, 0.0);  // and sides
  add(Polygon::quad({2, 0, 0}, {2, 1, 0}, {2, 1, h}, {2, 0, h}), 0.0, 0.0);
  add(Polygon::quad({1, 0, 0}, {2, 0, 0}, {2, 0, h}, {1, 0, h}), 0.0, 0.0);
  add(Polygon::quad({1, 1, 0}, {1, 1, h}, {2, 1, h}, {2, 1, 0}), 0.0, 0.0);
  scene.build_elements();
  for (std::size_t p = 3; p < scene.patches.size(); ++p)  // the box's faces face out of it
    ASSERT_LT(glm::dot(scene.patches[p].normal, Vec3(1.5, 0.5, h / 2) - scene.patches[p].polygon.centroid()), 0.0);

  const std::vector<Vec3> emitter = {{0, 0, 1}, {0, 1, 1}, {2, 1, 1}, {2, 0, 1}};
  const std::vector<Vec3> wall = {{0, 0, 0}, {0, 1, 0}, {0, 1, 1}, {0, 0, 1}};
  const std::vector<Vec3> open_floor = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  const double f_oc = rectangle_factor({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, emitter);
  const double f_ow = rectangle_factor({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, wall);
  const double f_wc = rectangle_factor({0, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 0}, emitter);
  EXPECT_NEAR(f_ow, perpendicular_rectangles(1, 1), 1e-4);  // the test's factors, checked
  const double b_open = 0.8 * (f_oc + f_ow * 0.5 * f_wc) / (1.0 - 0.8 * 0.5 * f_ow * f_ow);
  const double b_wall = 0.5 * (f_wc + f_ow * b_open);

  FormFactorOptions options;
  options.side = 16;
  options.threads = 1;
  std::vector<double> open;
  const FormFactors rows = area_form_factors(scene, options, nullptr, &open);
  EXPECT_EQ(open[0], 0.5);  // the 16 x 16 strata split at x = 1
  EXPECT_EQ(open[1], 1.0);
  const std::vector<Rgb> b = element_means(scene, solve_radiosity(scene, rows), open);
  std::printf("floor %.5f (exact %.5f), wall %.5f (exact %.5f)\n", b[0].r, 0.5 * b_open, b[1].r, b_wall);
  EXPECT_NEAR(b[0].r, 0.5 * b_open, 1e-2 * 0.5 * b_open);
  EXPECT_NEAR(b[1].r, b_wall, 1e-2 * b_wall);
}

TEST(ReferenceFormFactors, SolveMatchesTheTwoElementSystemByHand) {
  // B0 = E0 + r0 F01 B1, B1 = E1 + r1 F10 B0 (one channel per colour):
  // B0 = (E0 + r0 F01 E1) / (1 - r0 r1 F01 F10).
  Scene scene = scene_of({kFloor, kCeiling});
  scene.patches[0].emission = Rgb(1.0, 2.0, 0.0);
  scene.patches[0].reflectance = Rgb(0.3, 0.6, 0.9);
  scene.patches[1].emission = Rgb(0.0, 0.5, 4.0);
  scene.patches[1].reflectance = Rgb(0.8, 0.2, 0.5);
  // Held once (reciprocity): I_01 = 0.4 with open areas 1 and 0.4 / 0.7.
  const double f01 = 0.4, f10 = 0.7;
  const FormFactors rows({1.0, f01 / f10}, {{{1}, {f01}}, {}});
  ASSERT_NEAR(rows.factor(0, 1), f01, 1e-15);
  ASSERT_NEAR(rows.factor(1, 0), f10, 1e-15);
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

TEST(ReferenceFormFactors, PairsHeldOnceSolveToTheSameBitsAsRowsHeldBothWays) {
  // The solver reads each pair once (lower sums scattered, upper gathered); the test's own
  // Gauss-Seidel reads every F_ij from both-way rows, as the reference did when it held them:
  // the same answer to the last bit. A closed cube with a blocker inside (reflectance 0.5 to
  // 0.8, one emitting face), 3 x 3 elements a face, so that rows have both halves.
  std::vector<Polygon> faces = {
      kFloor, kCeiling, kWall,
      Polygon::quad({1, 0, 0}, {1, 0, 1}, {1, 1, 1}, {1, 1, 0}),
      Polygon::quad({0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}),
      Polygon::quad({0, 1, 0}, {1, 1, 0}, {1, 1, 1}, {0, 1, 1}),
      Polygon::quad({0.3, 0.3, 0.4}, {0.7, 0.3, 0.4}, {0.7, 0.7, 0.4}, {0.3, 0.7, 0.4})};
  Scene scene = scene_of(faces, 3);
  scene.patches[1].emission = Rgb(1.0, 0.8, 0.6);
  for (std::size_t p = 0; p < scene.patches.size(); ++p)
    scene.patches[p].reflectance = Rgb(0.5 + 0.05 * double(p), 0.6, 0.8 - 0.04 * double(p));
  const FormFactors factors = form_factors(scene, 4);
  ASSERT_GT(factors.pairs(), 300);
  constexpr int sweeps = 25;  // a fixed count (a tolerance below 0 is never met)
  SolveReport report;
  const std::vector<Rgb> once = solve_radiosity(scene, factors, -1.0, sweeps, &report);
  ASSERT_EQ(report.sweeps, sweeps);
  std::vector<std::vector<FormFactorEntry>> rows;
  for (int i = 0; i < factors.size(); ++i) rows.push_back(factors.row(i));
  std::vector<Rgb> b(scene.elements.size());
  for (std::size_t i = 0; i < b.size(); ++i) b[i] = scene.patches[std::size_t(scene.elements[i].patch)].emission;
  for (int sweep = 0; sweep < sweeps; ++sweep)
    for (std::size_t i = 0; i < b.size(); ++i) {
      Rgb gathered(0.0);
      for (const FormFactorEntry& e : rows[i]) gathered += e.value * b[std::size_t(e.element)];
      const Patch& patch = scene.patches[std::size_t(scene.elements[i].patch)];
      b[i] = patch.emission + patch.reflectance * gathered;
    }
  for (std::size_t i = 0; i < b.size(); ++i)
    for (int c = 0; c < 3; ++c) EXPECT_EQ(once[i][c], b[i][c]) << "element " << i << " colour " << c;
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

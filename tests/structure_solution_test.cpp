// The exact solution of the simulator's structure (src/reference/structure_solution.h,
// docs/accuracy.md "The error taken apart") against closed forms worked out here: the
// point-to-rectangle factor of a point under a corner of a parallel rectangle (Howell's
// catalogue, B-3), summed over the four rectangles a foot point cuts; two-level systems
// solved by hand; a half-hidden shooter.
#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>

#include "reference/structure_solution.h"

namespace ncube::reference {
namespace {

// Howell B-3: a differential area parallel to an a x b rectangle at distance c, on the normal
// through one of its corners.
double corner_factor(double a, double b, double c = 1.0) {
  const double x = a / c, y = b / c;
  const double x1 = std::sqrt(1 + x * x), y1 = std::sqrt(1 + y * y);
  return (x / x1 * std::atan(y / x1) + y / y1 * std::atan(x / y1)) / (2.0 * M_PI);
}

// A point at (px, py, 0) facing up, under the rectangle [x0, x1] x [y0, y1] at height c.
double under_rectangle(double px, double py, double x0, double x1, double y0, double y1,
                       double c = 1.0) {
  // Inclusion-exclusion over the corner rectangles from the foot point (px, py), each signed
  // by the side of the foot it lies on.
  const auto from_foot = [&](double u, double v) {
    const double sign = (u >= px ? 1.0 : -1.0) * (v >= py ? 1.0 : -1.0);
    return sign * corner_factor(std::fabs(u - px), std::fabs(v - py), c);
  };
  return from_foot(x1, y1) - from_foot(x0, y1) - from_foot(x1, y0) + from_foot(x0, y0);
}

const Polygon kFloor = Polygon::quad({0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0});
const Polygon kCeiling = Polygon::quad({0, 0, 1}, {0, 1, 1}, {1, 1, 1}, {1, 0, 1});

Scene two_squares(int floor_elements, Rgb floor_rho, Rgb ceiling_rho, Rgb ceiling_emission) {
  Scene scene;
  scene.name = "two squares";
  Patch floor;
  floor.polygon = kFloor;
  floor.reflectance = floor_rho;
  floor.nu = floor.nv = floor_elements;
  Patch ceiling;
  ceiling.polygon = kCeiling;
  ceiling.reflectance = ceiling_rho;
  ceiling.emission = ceiling_emission;
  scene.patches = {floor, ceiling};
  scene.build_elements();
  return scene;
}

StructureSolve solve(const Scene& scene, Structure structure, int side) {
  StructureOptions options;
  options.side = side;
  options.threads = 1;
  const Scene shooters = shooter_scene(scene, structure);
  return solve_structure(shooters, structure_form_factors(shooters, options));
}

TEST(StructureSolution, CornerFormulaAgreesWithQuadrature) {
  // The closed form above against a midpoint quadrature of the kernel c^2 / (pi r^4) over the
  // rectangle (the check of the formula is the test's own, not the code's).
  for (const auto& [px, py] : {std::pair{0.5, 0.5}, std::pair{0.25, 0.75}, std::pair{1.3, -0.2}}) {
    const int n = 1000;
    double sum = 0.0;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const double x = (i + 0.5) / n - px, y = (j + 0.5) / n - py;
        const double r2 = x * x + y * y + 1.0;
        sum += 1.0 / (M_PI * r2 * r2);
      }
    EXPECT_NEAR(under_rectangle(px, py, 0, 1, 0, 1), sum / (double(n) * n), 1e-7) << px << " " << py;
  }
}

TEST(StructureSolution, DirectLightAtEveryElementCentre) {
  // An emitter of radiosity 1 over a floor of 2 x 2 elements (rho 0.5): each element takes
  // rho F(centre -> emitter), F the closed form from its centre; unoccluded, so exact.
  const Scene scene = two_squares(2, Rgb(0.5), Rgb(0.0), Rgb(1.0));
  const StructureSolve s = solve(scene, Structure::kPatches, 8);
  for (int e = 0; e < 4; ++e) {
    const Vec3 c = scene.elements[std::size_t(e)].centre;
    EXPECT_NEAR(s.radiosity[std::size_t(e)].g, 0.5 * under_rectangle(c.x, c.y, 0, 1, 0, 1), 1e-12)
        << "element " << e;
  }
  // What the emitter sends that the floor's centres receive: mean of F(centre -> emitter).
  EXPECT_NEAR(s.delivery[1], under_rectangle(0.25, 0.25, 0, 1, 0, 1), 1e-12);
}

TEST(StructureSolution, PatchShootsItsElementsMean) {
  // Both reflect (rho 0.5), the ceiling emits 1. Floor element e: B_e = 0.5 F_e B_c (all
  // four alike by symmetry, F_e from (0.25, 0.25)); the ceiling, one element, receives the
  // floor's mean: B_c = 1 + 0.5 F_c Bbar_f, F_c from the ceiling's centre to the whole floor.
  const Scene scene = two_squares(2, Rgb(0.5), Rgb(0.5), Rgb(1.0));
  const double fe = under_rectangle(0.25, 0.25, 0, 1, 0, 1);
  const double fc = under_rectangle(0.5, 0.5, 0, 1, 0, 1);
  const double bc = 1.0 / (1.0 - 0.25 * fc * fe);
  const StructureSolve s = solve(scene, Structure::kPatches, 8);
  EXPECT_NEAR(s.radiosity[4].r, bc, 1e-12);
  for (int e = 0; e < 4; ++e) EXPECT_NEAR(s.radiosity[std::size_t(e)].r, 0.5 * fe * bc, 1e-12);
  // Every element its own patch: the ceiling's centre sees each floor element as a 0.5 x 0.5
  // rectangle with a corner under it: B_c = 1 + 0.5 * 4 F_q * 0.5 F_e B_c.
  const double fq = corner_factor(0.5, 0.5);
  const StructureSolve own = solve(scene, Structure::kElements, 8);
  const double bc_own = 1.0 / (1.0 - fq * fe);
  EXPECT_NEAR(own.radiosity[4].r, bc_own, 1e-12);
  EXPECT_NEAR(own.radiosity[0].r, 0.5 * fe * bc_own, 1e-12);
}

TEST(StructureSolution, HalfHiddenShooter) {
  // A blocker on z = 0.5 over x < 0.3 hides the emitter's part x < 0.1 from the floor's
  // centre (0.5, 0.5, 0): F = the closed form over [0.1, 1] x [0, 1]. The shadow's edge cuts
  // cells of the shooter: sampled there, closer at K = 1024 than at K = 16.
  Scene scene = two_squares(1, Rgb(1.0), Rgb(0.0), Rgb(1.0));
  Patch blocker;
  blocker.polygon = Polygon::quad({-1, -1, 0.5}, {-1, 2, 0.5}, {0.3, 2, 0.5}, {0.3, -1, 0.5});
  scene.patches.push_back(blocker);
  scene.build_elements();
  const double exact = under_rectangle(0.5, 0.5, 0.1, 1, 0, 1);
  const double fine = solve(scene, Structure::kPatches, 32).radiosity[0].g;
  EXPECT_NEAR(fine, exact, 2e-3 * exact);
  const double coarse_error = std::fabs(solve(scene, Structure::kPatches, 4).radiosity[0].g - exact);
  EXPECT_LT(std::fabs(fine - exact), coarse_error);
  // With the edge on the cells' boundary (blocker to x < 0.5: the emitter's half x < 0.5
  // hidden; 16 cells a side) every cell is wholly seen or wholly hidden: exact.
  scene.patches[2].polygon = Polygon::quad({-1, -1, 0.5}, {-1, 2, 0.5}, {0.5, 2, 0.5}, {0.5, -1, 0.5});
  scene.build_elements();
  EXPECT_NEAR(solve(scene, Structure::kPatches, 32).radiosity[0].g,
              under_rectangle(0.5, 0.5, 0.5, 1, 0, 1), 1e-6);
}

TEST(StructureSolution, OneSided) {
  // The floor turned over (facing down, away from the emitter) receives nothing; the emitter
  // turned away from the floor sends nothing.
  Scene scene = two_squares(1, Rgb(0.5), Rgb(0.0), Rgb(1.0));
  scene.patches[0].polygon = Polygon::quad({0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0});
  scene.build_elements();
  EXPECT_EQ(solve(scene, Structure::kPatches, 4).radiosity[0].r, 0.0);
  scene = two_squares(1, Rgb(0.5), Rgb(0.0), Rgb(1.0));
  scene.patches[1].polygon = Polygon::quad({0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1});
  scene.build_elements();
  EXPECT_EQ(solve(scene, Structure::kPatches, 4).radiosity[0].r, 0.0);
}

StructureSolve solve_eye(const Scene& scene, Structure structure, int side,
                         StructureRows* rows_out = nullptr) {
  StructureOptions options;
  options.side = side;
  options.threads = 1;
  StructureRows rows = eye_form_factors(scene, structure, options);
  if (rows_out) *rows_out = rows;
  return solve_structure(scene, rows);
}

TEST(StructureSolution, HemicubeCentreIsThePointToElementFactorTurnedAround) {
  // The hemicube's own structure (one eye at the shooter's centroid): the emitting ceiling's
  // eye (0.5, 0.5, 1) sees each floor element, a 0.5 x 0.5 square with a corner under it at
  // distance 1 (Howell B-3), and reciprocity gives F(element -> ceiling) = A_ceiling F_q /
  // A_element = 4 F_q; B = rho 4 F_q. Unoccluded, every cell a closed form: exact.
  const Scene scene = two_squares(2, Rgb(0.5), Rgb(0.0), Rgb(1.0));
  const double fq = corner_factor(0.5, 0.5);
  StructureRows rows;
  const StructureSolve s = solve_eye(scene, Structure::kHemicubeCentre, 4, &rows);
  for (int e = 0; e < 4; ++e) {
    ASSERT_EQ(rows[std::size_t(e)].size(), 1u);
    EXPECT_EQ(rows[std::size_t(e)][0].shooter, 1);
    EXPECT_NEAR(rows[std::size_t(e)][0].value, 4.0 * fq, 1e-12) << "element " << e;
    EXPECT_NEAR(s.radiosity[std::size_t(e)].g, 0.5 * 4.0 * fq, 1e-12);
  }
  // Not the receiver-centred structure's: F(centre of an element -> ceiling) differs.
  EXPECT_GT(std::fabs(4.0 * fq - under_rectangle(0.25, 0.25, 0, 1, 0, 1)), 0.01);
}

TEST(StructureSolution, HemicubeElementsSumsAnEyeAtEveryShooterElement) {
  // The ceiling cut into 2 x 2 elements: an eye at each of their centroids (x, y in {0.25,
  // 0.75}), each of area 0.25: F(floor element -> ceiling) = sum_j 0.25 F(c_j -> e) / 0.25.
  Scene scene = two_squares(2, Rgb(0.5), Rgb(0.0), Rgb(1.0));
  scene.patches[1].nu = scene.patches[1].nv = 2;
  scene.build_elements();
  StructureRows rows;
  solve_eye(scene, Structure::kHemicubeElements, 4, &rows);
  for (int e = 0; e < 4; ++e) {
    const Polygon& p = scene.elements[std::size_t(e)].polygon;
    double x0 = 1, x1 = 0, y0 = 1, y1 = 0;
    for (int c = 0; c < p.count; ++c) {
      x0 = std::min(x0, p[c].x), x1 = std::max(x1, p[c].x);
      y0 = std::min(y0, p[c].y), y1 = std::max(y1, p[c].y);
    }
    double expected = 0.0;
    for (double ex : {0.25, 0.75})
      for (double ey : {0.25, 0.75}) expected += under_rectangle(ex, ey, x0, x1, y0, y1);
    ASSERT_EQ(rows[std::size_t(e)].size(), 1u);
    EXPECT_NEAR(rows[std::size_t(e)][0].value, expected, 1e-12) << "element " << e;
  }
}

TEST(StructureSolution, HemicubeReciprocityAboveOneIsKept) {
  // A 0.02 x 0.02 receiver 0.01 below the emitter's centre, facing it: F(eye -> receiver) is
  // that of a square of half-side 1 at distance 1 (4 x Howell B-3 (1, 1)), and reciprocity
  // multiplies it by A_emitter / A_receiver = 2,500: far above 1, as the hemicube has it.
  Scene scene = two_squares(1, Rgb(0.5), Rgb(0.0), Rgb(1.0));
  scene.patches[0].polygon = Polygon::quad({0.49, 0.49, 0.99}, {0.51, 0.49, 0.99}, {0.51, 0.51, 0.99},
                                           {0.49, 0.51, 0.99});
  scene.build_elements();
  StructureRows rows;
  solve_eye(scene, Structure::kHemicubeCentre, 4, &rows);
  ASSERT_EQ(rows[0].size(), 1u);
  const double point = 4.0 * corner_factor(1.0, 1.0);
  EXPECT_NEAR(rows[0][0].value, point / 0.0004, 1e-9 * point / 0.0004);
  EXPECT_GT(rows[0][0].value, 1.0);
}

TEST(StructureSolution, HemicubeStructureHidesAndIsOneSided) {
  // A blocker at z = 0.5 over the whole floor's half x < 0.5 hides from the ceiling's eye
  // (0.5, 0.5, 1) every floor point with x < 0.5 (the rays go down and towards x = 0.5 from
  // x = 0.5: a point at x < 0.5 is reached through z = 0.5 at x < 0.5): the two elements at
  // x < 0.5 receive nothing, the two others their whole factor.
  Scene scene = two_squares(2, Rgb(0.5), Rgb(0.0), Rgb(1.0));
  Patch blocker;
  blocker.polygon = Polygon::quad({-1, -1, 0.5}, {-1, 2, 0.5}, {0.5, 2, 0.5}, {0.5, -1, 0.5});
  scene.patches.push_back(blocker);
  scene.build_elements();
  StructureRows rows;
  solve_eye(scene, Structure::kHemicubeCentre, 4, &rows);
  const double fq = corner_factor(0.5, 0.5);
  for (int e = 0; e < 4; ++e) {
    const bool hidden = scene.elements[std::size_t(e)].centre.x < 0.5;
    double to_ceiling = 0.0;
    for (const StructureEntry& entry : rows[std::size_t(e)])
      if (entry.shooter == 1) to_ceiling = entry.value;
    EXPECT_NEAR(to_ceiling, hidden ? 0.0 : 4.0 * fq, 1e-9) << "element " << e;
  }
  // The floor turned over (its back to the eye) receives nothing.
  scene = two_squares(1, Rgb(0.5), Rgb(0.0), Rgb(1.0));
  scene.patches[0].polygon = Polygon::quad({0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0});
  scene.build_elements();
  EXPECT_EQ(solve_eye(scene, Structure::kHemicubeCentre, 4).radiosity[0].r, 0.0);
}

TEST(StructureSolution, StructureNames) {
  for (Structure s : {Structure::kPatches, Structure::kElements, Structure::kHemicubeCentre,
                      Structure::kHemicubeElements}) {
    Structure back = Structure::kPatches;
    ASSERT_TRUE(structure_of(structure_name(s), &back));
    EXPECT_EQ(back, s);
  }
  Structure unused;
  EXPECT_FALSE(structure_of("hemicube", &unused));
}

}  // namespace
}  // namespace ncube::reference

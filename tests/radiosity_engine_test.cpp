#include "radiosity/radiosity_engine.h"

#include <gtest/gtest.h>

#include "host/fast_occluders.h"
#include <numeric>

namespace ncube {
namespace {

Patch face(const Vec3& origin, const Vec3& u, const Vec3& v, int n, double reflectance,
           double emission) {
  Patch p;
  p.polygon = Polygon::quad(origin, origin + u, origin + u + v, origin + v);
  p.reflectance = Rgb(reflectance);
  p.emission = Rgb(emission);
  p.nu = p.nv = n;
  return p;
}

// The unit cube seen from inside: six faces, normals pointing inwards.
Scene closed_box(int n, double reflectance, double emission_all, double emission_floor) {
  Scene s;
  s.name = "box";
  const Vec3 X(1, 0, 0), Y(0, 1, 0), Z(0, 0, 1), O(0, 0, 0);
  s.patches = {face(O, Z, X, n, reflectance, emission_all + emission_floor),  // floor
               face(Y, X, Z, n, reflectance, emission_all),                   // ceiling
               face(O, Y, Z, n, reflectance, emission_all),                   // x = 0
               face(X, Z, Y, n, reflectance, emission_all),                   // x = 1
               face(O, X, Y, n, reflectance, emission_all),                   // z = 0
               face(Z, Y, X, n, reflectance, emission_all)};                  // z = 1
  s.build_elements();
  return s;
}

std::vector<int> all_patches(const Scene& s) {
  std::vector<int> v(s.patches.size());
  std::iota(v.begin(), v.end(), 0);
  return v;
}

TEST(RadiosityEngine, WhiteFurnaceConvergesToEmissionOverOneMinusReflectance) {
  const double E = 1.0, rho = 0.5;
  const Scene box = closed_box(8, rho, E, 0.0);
  RadiosityEngine engine(box, all_patches(box));
  const FastOccluders occluders(box, all_patches(box), RayTestPolicy::kTestAllPatches);
  ProgressiveOptions options;
  options.samples = 16;  // M = 16 (the paper's smaller M), as when it was the default
  options.convergence_fraction = 1e-6;
  const ProgressiveRun run = run_progressive(engine, occluders, options);
  ASSERT_TRUE(run.converged);
  for (int e = 0; e < int(box.elements.size()); ++e)
    for (int c = 0; c < 3; ++c)
      ASSERT_NEAR(engine.element_radiosity(e)[c], E / (1 - rho), 0.01 * E / (1 - rho)) << e;
}

TEST(RadiosityEngine, OneShotInAClosedBoxDeliversAllTheShootersPower) {
  // Conservation: in a closed box every bit of the shooter's power lands on some element.
  const double rho = 0.5;
  const Scene box = closed_box(20, rho, 0.0, 1.0);
  RadiosityEngine engine(box, all_patches(box));
  const FastOccluders occluders(box, all_patches(box), RayTestPolicy::kTestAllPatches);
  ProgressiveOptions options;
  options.samples = 16;  // M = 16 (the paper's smaller M), as when it was the default
  options.max_iterations = 1;
  run_progressive(engine, occluders, options);
  double received = 0.0;
  for (const Element& e : box.elements)
    if (e.patch != 0) received += engine.element_radiosity(&e - &box.elements[0]).r / rho * e.area;
  const double shot = 1.0 * box.patches[0].area;
  EXPECT_NEAR(received / shot, 1.0, 0.01);
  EXPECT_EQ(engine.unshot(0), Rgb(0.0));
}

TEST(RadiosityEngine, TotalPowerNeverExceedsTheGeometricSeriesBound) {
  const double rho = 0.7;
  const Scene box = closed_box(6, rho, 0.0, 2.0);
  RadiosityEngine engine(box, all_patches(box));
  const FastOccluders occluders(box, all_patches(box), RayTestPolicy::kTestAllPatches);
  ProgressiveOptions options;
  options.samples = 16;  // M = 16 (the paper's smaller M), as when it was the default
  options.convergence_fraction = 1e-4;
  run_progressive(engine, occluders, options);
  double power = 0.0;
  for (int e = 0; e < int(box.elements.size()); ++e)
    power += engine.element_radiosity(e).g * box.elements[e].area;
  const double emitted = 2.0 * box.patches[0].area;
  EXPECT_LE(power, emitted / (1 - rho) * 1.01);
  EXPECT_GE(power, emitted / (1 - rho) * 0.97);  // nearly all reflections accounted for
}

TEST(RadiosityEngine, ABlockerCastsAShadow) {
  Scene s;
  s.name = "shadow";
  // Light above, floor below, a square blocker in between over the floor's centre.
  s.patches = {face({-1, 2, -1}, {0, 0, 2}, {2, 0, 0}, 1, 0.0, 1.0),      // light, facing down
               face({-2, 0, -2}, {0, 0, 4}, {4, 0, 0}, 9, 0.5, 0.0),      // floor, facing up
               face({-1.5, 1, -1.5}, {0, 0, 3}, {3, 0, 0}, 1, 0.5, 0.0)};  // blocker, facing up
  s.patches[0].polygon = Polygon::quad({-0.2, 2, -0.2}, {0.2, 2, -0.2}, {0.2, 2, 0.2}, {-0.2, 2, 0.2});
  s.build_elements();
  RadiosityEngine engine(s, all_patches(s));
  const FastOccluders occluders(s, all_patches(s), RayTestPolicy::kTestAllPatches);
  ProgressiveOptions options;
  options.samples = 16;  // M = 16 (the paper's smaller M), as when it was the default
  options.max_iterations = 1;
  const ProgressiveRun run = run_progressive(engine, occluders, options);
  ASSERT_EQ(run.shooters, std::vector<int>{0});
  const Patch& floor = s.patches[1];
  const int centre = floor.first_element + 4 * 9 + 4;
  const int corner = floor.first_element;
  EXPECT_EQ(engine.element_radiosity(centre), Rgb(0.0));  // in the blocker's shadow
  EXPECT_EQ(engine.element_radiosity(corner), Rgb(0.0));  // also shadowed: blocker is wide
  EXPECT_GT(engine.element_radiosity(s.patches[2].first_element).r, 0.0);  // blocker top is lit
}

TEST(RadiosityEngine, ShootsTheBrightestPatchFirst) {
  const Scene box = closed_box(2, 0.5, 0.0, 1.0);
  RadiosityEngine engine(box, all_patches(box));
  WorkCounts counts;
  const ShooterChoice best = engine.best_shooter(counts);
  EXPECT_EQ(best.patch, 0);
  EXPECT_DOUBLE_EQ(best.power, 3.0 * 1.0);  // (r+g+b) x area
  EXPECT_EQ(counts.shooter_candidates, 6u);
}

}  // namespace
}  // namespace ncube

namespace ncube {
namespace {

TEST(RadiosityEngine, TracingFromReceiversThatCannotSeeTheShooterChangesWorkNotLight) {
  // A light in the middle of a box facing down: the ceiling and the upper walls cannot see
  // its front. Tracing their rays anyway costs rays but adds no light.
  Scene s = closed_box(6, 0.5, 0.0, 0.0);
  Patch light = face({0.4, 0.5, 0.4}, {0.2, 0, 0}, {0, 0, 0.2}, 1, 0.0, 5.0);  // facing down
  s.patches.push_back(light);
  s.build_elements();
  ProgressiveOptions skip, trace_all;
  skip.samples = trace_all.samples = 16;  // M = 16, as when it was the default
  skip.max_iterations = trace_all.max_iterations = 1;  // the light shoots
  skip.skip_facing_away = true;
  trace_all.skip_facing_away = false;  // the default
  RadiosityEngine a(s, all_patches(s)), b(s, all_patches(s));
  const FastOccluders occluders(s, all_patches(s), RayTestPolicy::kTestAllPatches);
  const ProgressiveRun run_a = run_progressive(a, occluders, skip);
  const ProgressiveRun run_b = run_progressive(b, occluders, trace_all);
  EXPECT_GT(run_b.total.rays, run_a.total.rays);
  for (int e = 0; e < int(s.elements.size()); ++e)
    ASSERT_EQ(a.element_radiosity(e), b.element_radiosity(e)) << e;
  EXPECT_EQ(a.element_radiosity(s.patches[1].first_element), Rgb(0.0));  // ceiling stays dark
}

}  // namespace
}  // namespace ncube

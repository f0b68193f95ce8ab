// The fast face tests (src/models/face_shapes.cpp: a k-d tree for the diameter, a sweep for
// crossing edges, a grid and kept ear states for ear clipping) against their quadratic
// references (src/models/face_shapes_reference.cpp) on many random polygons: the same double,
// the same first crossing pair, the same triangles in the same order.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <glm/common.hpp>

#include "models/face_shapes.h"
#include "models/face_shapes_reference.h"

namespace ncube::models {
namespace {

using Polygon = std::vector<Point>;

// A polygon around the origin: n corners at sorted random angles and random radii (star-shaped,
// simple, concave where a radius dips), lifted off the plane z = 0 by up to `bend`.
Polygon star(std::mt19937& random, std::size_t n, double inner, double bend) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<double> angle(n);
  for (double& a : angle) a = 2 * M_PI * unit(random);
  std::sort(angle.begin(), angle.end());
  Polygon p;
  for (const double a : angle) {
    const double r = inner + (1 - inner) * unit(random);
    p.emplace_back(r * std::cos(a), r * std::sin(a), bend * unit(random));
  }
  return p;
}

// A spiral strip: out along one arm and back along a parallel one.
Polygon spiral(std::size_t half, double turns, double width) {
  Polygon p;
  for (std::size_t k = 0; k < half; ++k) {
    const double a = 2 * M_PI * turns * double(k) / double(half), r = 1 + a;
    p.emplace_back(r * std::cos(a), r * std::sin(a), 0.0);
  }
  for (std::size_t k = half; k-- > 0;) {
    const double a = 2 * M_PI * turns * double(k) / double(half), r = 1 + a + width;
    p.emplace_back(r * std::cos(a), r * std::sin(a), 0.0);
  }
  return p;
}

// A comb of `teeth` teeth, the usual hard case for ear clipping (ears found late).
Polygon comb(std::size_t teeth) {
  Polygon p;
  for (std::size_t t = 0; t < teeth; ++t) {
    const double x = 2.0 * double(t);
    p.insert(p.end(), {{x, 10, 0}, {x, 1, 0}, {x + 1, 1, 0}, {x + 1, 10, 0}});
  }
  p.insert(p.end(), {{2.0 * double(teeth), 0, 0}, {-1, 0, 0}});
  std::reverse(p.begin(), p.end());
  return p;
}

// A rectangle whose sides carry many corners on a line, each moved off it by up to `noise`.
Polygon subdivided_rectangle(std::mt19937& random, std::size_t per_side, double noise) {
  std::uniform_real_distribution<double> jitter(-noise, noise);
  Polygon p;
  const double step = 1.0 / double(per_side);
  for (std::size_t k = 0; k < per_side; ++k) p.emplace_back(double(k) * step, jitter(random), 0.0);
  for (std::size_t k = 0; k < per_side; ++k) p.emplace_back(1 + jitter(random), double(k) * step * 0.5, 0.0);
  for (std::size_t k = 0; k < per_side; ++k) p.emplace_back(1 - double(k) * step, 0.5 + jitter(random), 0.0);
  for (std::size_t k = 0; k < per_side; ++k) p.emplace_back(jitter(random), 0.5 - double(k) * step * 0.5, 0.0);
  return p;
}

// Random corners in a square, in random order (an outline crossing itself many times), on a
// coarse integer lattice when `lattice` (repeated corners, exactly collinear ones).
Polygon scribble(std::mt19937& random, std::size_t n, bool lattice) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Polygon p;
  for (std::size_t k = 0; k < n; ++k) {
    Point c(unit(random), unit(random), 0.01 * unit(random));
    if (lattice) c = glm::floor(c * 6.0);
    p.push_back(c);
  }
  return p;
}

// Some corners of `p` repeated: next to themselves, or a later corner at an earlier one's place.
Polygon with_repeats(std::mt19937& random, Polygon p) {
  std::uniform_int_distribution<std::size_t> pick(0, p.size() - 1);
  for (int k = 0; k < 3; ++k) {
    const std::size_t i = pick(random);
    p.insert(p.begin() + std::ptrdiff_t(i), p[i]);
  }
  p[pick(random)] = p[pick(random)];
  return p;
}

void expect_same(const Polygon& p, const std::string& what) {
  SCOPED_TRACE(what + ", " + std::to_string(p.size()) + " corners");
  EXPECT_EQ(diameter(p), reference::diameter(p));
  EXPECT_EQ(crossing_edges(p), reference::crossing_edges(p));
  EXPECT_EQ(ear_clip(p), reference::ear_clip(p));
}

TEST(FaceShapesFast, StarShapedAndConcavePolygonsGiveTheReferencesAnswers) {
  std::mt19937 random(7);
  for (const std::size_t n : {5, 6, 9, 20, 47, 48, 49, 100, 333, 700})
    for (const double inner : {1.0, 0.9, 0.3, 0.01})
      for (const double bend : {0.0, 0.05}) expect_same(star(random, n, inner, bend), "star");
}

// The diameter's search works on squares in the face's units: faces tiny, huge, and tiny far
// from the origin (too small beside their place for squares) keep the reference's double.
TEST(FaceShapesFast, TheDiameterIsTheReferencesAtAnyScale) {
  std::mt19937 random(5);
  for (const double scale : {1e-300, 1e-150, 1e-20, 1e20, 1e150, 1e300})
    for (const Point offset : {Point(0.0), Point(1.0, 2.0, 3.0)}) {
      Polygon p = star(random, 200, 0.5, 0.1);
      for (Point& c : p) c = c * scale + offset;
      SCOPED_TRACE(std::to_string(scale));
      EXPECT_EQ(diameter(p), reference::diameter(p));
    }
}

TEST(FaceShapesFast, SpiralsAndCombsGiveTheReferencesAnswers) {
  for (const std::size_t half : {30, 200, 500})
    for (const double turns : {0.5, 2.0, 5.0}) expect_same(spiral(half, turns, 0.5), "spiral");
  for (const std::size_t teeth : {2, 13, 60, 250}) expect_same(comb(teeth), "comb");
}

TEST(FaceShapesFast, NearlyCollinearAndRepeatedCornersGiveTheReferencesAnswers) {
  std::mt19937 random(11);
  for (const std::size_t per_side : {3, 25, 100, 200})
    for (const double noise : {0.0, 1e-17, 1e-14, 1e-9, 1e-4}) {
      expect_same(subdivided_rectangle(random, per_side, noise), "rectangle");
      expect_same(with_repeats(random, subdivided_rectangle(random, per_side, noise)), "rectangle, repeats");
    }
  for (const std::size_t n : {8, 50, 300}) {
    expect_same(with_repeats(random, star(random, n, 0.5, 0.0)), "star, repeats");
    expect_same(with_repeats(random, comb(n / 4)), "comb, repeats");
  }
}

TEST(FaceShapesFast, OutlinesThatCrossThemselvesGiveTheReferencesFirstPair) {
  std::mt19937 random(13);
  for (const std::size_t n : {4, 5, 7, 30, 200, 600})
    for (const bool lattice : {false, true}) expect_same(scribble(random, n, lattice), "scribble");
  // One crossing late in a large simple outline: the pair the reference names.
  Polygon ring = star(random, 2000, 1.0, 0.0);
  ring.insert(ring.begin() + 1500, {Point(0.5, 0.5, 0), Point(-0.5, -0.5, 0)});
  EXPECT_EQ(crossing_edges(ring), reference::crossing_edges(ring));
  EXPECT_TRUE(crossing_edges(ring).has_value());
}

}  // namespace
}  // namespace ncube::models

// AxisPatchTest answers the exact ray-patch test for axis-aligned rectangles in fewer
// operations (host/axis_patch_test.h); it must give segment_crosses' answer for every ray,
// in particular rays aimed at edges and corners, at the doubles next to them, and rays
// parallel to or lying in the plane. The rectangles get their normals as the scene loader
// makes them (normalised cross product), which are often not exactly +-1.
#include "host/axis_patch_test.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "axis_rectangles.h"

namespace ncube {
namespace {

TEST(AxisPatchTest, TakesTheFastFormForAxisRectanglesWithTheLoadersNormals) {
  const std::vector<PatchCandidate> patches = rectangles();
  const AxisPatchTest fast(patches);
  int not_exactly_one = 0;
  for (int p = 0; p < int(patches.size()); ++p) {
    EXPECT_TRUE(fast.fast(p)) << p;
    for (int axis = 0; axis < 3; ++axis)
      not_exactly_one += std::fabs(patches[std::size_t(p)].normal[axis]) > 0.5 &&
                         std::fabs(patches[std::size_t(p)].normal[axis]) != 1.0;
  }
  EXPECT_GT(not_exactly_one, 0) << "some normals should be +-1 only up to rounding";
}

TEST(AxisPatchTest, AgreesWithTheExactTestAtEdgesCornersAndTheirNeighbouringDoubles) {
  const std::vector<PatchCandidate> patches = rectangles();
  const AxisPatchTest fast(patches);
  std::mt19937_64 random(2026);
  std::uniform_real_distribution<double> coordinate(-2.0, 14.0);
  long compared = 0, crossing = 0;
  for (int p = 0; p < int(patches.size()); ++p) {
    const PatchCandidate& c = patches[std::size_t(p)];
    const int axis = c.normal.x != 0.0 ? 0 : (c.normal.y != 0.0 ? 1 : 2);
    for (const Vec3& aim : aim_points(c, random))
      for (int trial = 0; trial < 8; ++trial) {
        // From a random point through the aim point, on to a point beyond it; sometimes
        // from a point in the plane itself (the ray lies in it), or ending on the plane.
        Vec3 from(coordinate(random), coordinate(random), coordinate(random));
        if (trial == 0) from[axis] = aim[axis];
        Vec3 to = aim + (aim - from) * (trial == 1 ? 0.0 : 0.25 + 0.5 * (trial % 3));
        const Vec3 delta = to - from;
        const bool expected = segment_crosses(c, from, delta);
        ASSERT_EQ(fast.crosses(p, from, delta), expected)
            << "patch " << p << " from " << from.x << "," << from.y << "," << from.z;
        ++compared;
        crossing += expected;
      }
  }
  // Both answers occur often (the aim points straddle every edge).
  EXPECT_GT(crossing, compared / 10);
  EXPECT_LT(crossing, compared * 9 / 10);
}

TEST(AxisPatchTest, LeavesOtherPatchesAndHugeScenesToTheExactTest) {
  std::vector<PatchCandidate> patches;
  const Polygon slanted = Polygon::quad(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 1), Vec3(0, 1, 1));
  patches.push_back(make_candidate(slanted, slanted.normal(), 0));
  const Polygon triangle = Polygon::triangle(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0));
  patches.push_back(make_candidate(triangle, triangle.normal(), 1));
  const AxisPatchTest fast(patches);
  EXPECT_FALSE(fast.fast(0));
  EXPECT_FALSE(fast.fast(1));
  EXPECT_EQ(fast.crosses(0, Vec3(0.5, 2, -1), Vec3(0, -2, 2)),
            segment_crosses(patches[0], Vec3(0.5, 2, -1), Vec3(0, -2, 2)));

  // Coordinates beyond kMaxCoordinate: products could leave the double range, where the
  // zero terms of the exact test are no longer zero (0 * inf): every patch takes the test.
  std::vector<PatchCandidate> huge = rectangles();
  const Polygon far = Polygon::quad(Vec3(0, 0, 1e200), Vec3(1e200, 0, 1e200), Vec3(1e200, 1e200, 1e200),
                                    Vec3(0, 1e200, 1e200));
  huge.push_back(make_candidate(far, far.normal(), int(huge.size())));
  const AxisPatchTest careful(huge);
  for (int p = 0; p < int(huge.size()); ++p) EXPECT_FALSE(careful.fast(p)) << p;
}

TEST(AxisPatchTest, SidesAgreeWithTheLoopsSideTestAtTheTolerance) {
  const std::vector<PatchCandidate> patches = rectangles();
  const AxisPatchTest fast(patches);
  const double tolerance = 1e-9 * 20.0;
  long apart_from_unit_normal = 0;
  for (int p = 0; p < int(patches.size()); ++p) {
    const PatchCandidate& c = patches[std::size_t(p)];
    const int axis = c.normal.x != 0.0 ? 0 : (c.normal.y != 0.0 ? 1 : 2);
    for (double edge : {c.plane_offset + tolerance, c.plane_offset - tolerance}) {
      Vec3 x(0.3, -0.2, 0.9);
      x[axis] = edge / c.normal[axis];
      for (int s = 0; s < 30; ++s) x[axis] = std::nextafter(x[axis], -1e300);
      for (int step = 0; step < 60; ++step, x[axis] = std::nextafter(x[axis], 1e300)) {
        const double distance = glm::dot(c.normal, x) - c.plane_offset;
        const int expected = distance > tolerance ? 1 : (distance < -tolerance ? -1 : 0);
        ASSERT_EQ(fast.side(p, x, tolerance), expected) << p;
        const double unit = std::copysign(1.0, c.normal[axis]) * x[axis] - c.plane_offset;
        apart_from_unit_normal += (unit > tolerance) != (distance > tolerance) ||
                                  (unit < -tolerance) != (distance < -tolerance);
      }
    }
  }
  // Some heights are classed otherwise by a normal taken as exactly +-1.
  EXPECT_GT(apart_from_unit_normal, 0);
}

}  // namespace
}  // namespace ncube

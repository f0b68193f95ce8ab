// The leaf tests of octree_lanes.h, eight rays at a time, in each compiled variant the host
// runs, against AxisPatchTest's scalar crosses and side (host/axis_patch_test.h) ray by ray:
// rays aimed at edges, corners and their neighbouring doubles, rays whose parameter is
// exactly the test's end (kRayEpsilon, 1 - kRayEpsilon) or next to it, targets walked double
// by double across the side tolerance, and gaps in the rays asked about. (The slab tests are
// compared with the literal walk in tests/fast_octree_test.cpp.)
#include "host/octree_lanes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "axis_rectangles.h"
#include "host/axis_patch_test.h"

namespace ncube {
namespace {

using octree_lanes::Isa;

std::vector<Isa> host_variants() {
  std::vector<Isa> variants;
  for (const Isa isa : {Isa::kSse2, Isa::kAvx2, Isa::kAvx512})
    if (octree_lanes::host_runs(isa)) variants.push_back(isa);
  return variants;
}

struct Tally {
  long rays = 0, blocked = 0, crossing = 0;
};

// The rays from `from` to `targets` (at most 64) against patch p, asking those in `asking`:
// each ray's bits as the scalar tests give them, none outside `asking`.
void expect_as_scalar(const AxisPatchTest& fast, int p, const Vec3& from, const std::vector<Vec3>& targets,
                      std::uint64_t asking, double tolerance, Isa isa, Tally& tally) {
  ASSERT_TRUE(fast.fast(p));
  ASSERT_LE(targets.size(), std::size_t(octree_lanes::kRays));
  double delta[3][octree_lanes::kRays] = {}, target_on_axis[3][octree_lanes::kRays] = {};
  for (std::size_t r = 0; r < targets.size(); ++r)
    for (int axis = 0; axis < 3; ++axis) {
      delta[axis][r] = targets[r][axis] - from[axis];
      target_on_axis[axis][r] = targets[r][axis];
    }
  if (targets.size() < 64) asking &= (std::uint64_t(1) << targets.size()) - 1;
  const AxisPatchTest::Record& record = fast.record(p);
  const int side_of_from = fast.side(p, from, tolerance);
  const octree_lanes::LeafQuery query{record.axis, record.edges, record.other, record.normal,
                                      record.offset, record.signed_length, record.corner,
                                      &from.x, {delta[0], delta[1], delta[2]},
                                      target_on_axis[record.axis], tolerance, side_of_from,
                                      asking};
  const octree_lanes::LeafAnswer answer = octree_lanes::kernels(isa).leaf_tests(query);
  for (std::size_t r = 0; r < targets.size(); ++r) {
    const bool asked = asking >> r & 1;
    const Vec3 d = targets[r] - from;
    const bool blocks = asked && fast.crosses(p, from, d);
    const bool crossing = asked && side_of_from * fast.side(p, targets[r], tolerance) < 0;
    ASSERT_EQ(bool(answer.blocked >> r & 1), blocks)
        << octree_lanes::isa_name(isa) << ": patch " << p << ", ray " << r;
    ASSERT_EQ(bool(answer.crossing >> r & 1), crossing)
        << octree_lanes::isa_name(isa) << ": patch " << p << ", ray " << r;
    tally.rays += asked;
    tally.blocked += blocks;
    tally.crossing += crossing;
  }
}

TEST(OctreeLanes, LeafTestsAgreeWithTheScalarTestsAtEdgesAndCorners) {
  const std::vector<PatchCandidate> patches = rectangles();
  const AxisPatchTest fast(patches);
  const double tolerance = 1e-9 * 20.0;
  for (const Isa isa : host_variants()) {
    std::mt19937_64 random(2026);
    std::uniform_real_distribution<double> coordinate(-2.0, 14.0);
    Tally tally;
    for (int p = 0; p < int(patches.size()); ++p) {
      const PatchCandidate& c = patches[std::size_t(p)];
      const std::vector<Vec3> aims = aim_points(c, random);
      // One point per packet, its rays through the aim points and on beyond them (or
      // ending on the plane); every third packet asks about every other ray only.
      for (std::size_t first = 0; first < aims.size(); first += 64) {
        const Vec3 from(coordinate(random), coordinate(random), coordinate(random));
        std::vector<Vec3> targets;
        for (std::size_t k = first; k < aims.size() && k < first + 64; ++k)
          targets.push_back(aims[k] + (aims[k] - from) * (k % 4 == 0 ? 0.0 : 0.25 * double(k % 4)));
        const std::uint64_t asking = first % 192 == 128 ? 0x5555555555555555ull : ~std::uint64_t(0);
        expect_as_scalar(fast, p, from, targets, asking, tolerance, isa, tally);
      }
    }
    EXPECT_GT(tally.blocked, tally.rays / 10) << octree_lanes::isa_name(isa);
    EXPECT_LT(tally.blocked, tally.rays * 9 / 10) << octree_lanes::isa_name(isa);
    EXPECT_GT(tally.crossing, tally.rays / 10) << octree_lanes::isa_name(isa);
  }
}

TEST(OctreeLanes, LeafTestsAgreeAtTheEndsOfTheRaysParameter) {
  // The plane z = 0 with a normal of exactly +1: from z = -e to z = 1 - e is t = e exactly
  // (numerator e, denominator 1), for e = kRayEpsilon and 1 - kRayEpsilon, and the doubles
  // next to them (the test's interval is open at both ends).
  const Polygon square = Polygon::quad(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0));
  const std::vector<PatchCandidate> patches{make_candidate(square, Vec3(0, 0, 1), 0)};
  const AxisPatchTest fast(patches);
  for (const Isa isa : host_variants()) {
    Tally tally;
    for (const double end : {kRayEpsilon, 1.0 - kRayEpsilon})
      for (int step = -3; step <= 3; ++step) {
        double z = -end;
        for (int s = 0; s < std::abs(step); ++s) z = std::nextafter(z, step > 0 ? 1.0 : -1.0);
        const Vec3 from(0.5, 0.5, z);
        std::vector<Vec3> targets;
        for (int k = 0; k < 11; ++k) targets.push_back(from + Vec3(0.01 * k, -0.02 * k, 1.0));
        expect_as_scalar(fast, 0, from, targets, ~std::uint64_t(0), 1e-12, isa, tally);
      }
    EXPECT_GT(tally.blocked, 0) << octree_lanes::isa_name(isa);
    EXPECT_LT(tally.blocked, tally.rays) << octree_lanes::isa_name(isa);
  }
}

TEST(OctreeLanes, CrossingsAgreeWithTheSideTestAtTheTolerance) {
  const std::vector<PatchCandidate> patches = rectangles();
  const AxisPatchTest fast(patches);
  const double tolerance = 1e-9 * 20.0;
  for (const Isa isa : host_variants()) {
    Tally tally;
    for (int p = 0; p < int(patches.size()); ++p) {
      const PatchCandidate& c = patches[std::size_t(p)];
      const int axis = c.normal.x != 0.0 ? 0 : (c.normal.y != 0.0 ? 1 : 2);
      for (const double edge : {c.plane_offset + tolerance, c.plane_offset - tolerance}) {
        // Targets 64 doubles across the tolerance; the point well in front, well behind or
        // on the plane.
        Vec3 x(0.3, -0.2, 0.9);
        x[axis] = edge / c.normal[axis];
        for (int s = 0; s < 32; ++s) x[axis] = std::nextafter(x[axis], -1e300);
        std::vector<Vec3> targets;
        for (int step = 0; step < 64; ++step, x[axis] = std::nextafter(x[axis], 1e300)) targets.push_back(x);
        for (const double height : {1.0, -1.0, 0.0}) {
          Vec3 from(0.25, 0.1, -0.05);
          from[axis] = c.plane_offset / c.normal[axis] + height;
          expect_as_scalar(fast, p, from, targets, ~std::uint64_t(0), tolerance, isa, tally);
        }
      }
    }
    EXPECT_GT(tally.crossing, tally.rays / 10) << octree_lanes::isa_name(isa);
    EXPECT_LT(tally.crossing, tally.rays / 2) << octree_lanes::isa_name(isa);
  }
}

}  // namespace
}  // namespace ncube

#include "host/near_patches.h"

#include <gtest/gtest.h>

#include <random>

namespace ncube {
namespace {

PatchCandidate quad(const Vec3& o, const Vec3& u, const Vec3& v, int index) {
  const Polygon p = Polygon::quad(o, o + u, o + u + v, o + v);
  return make_candidate(p, p.normal(), index);
}

// The literal definition: every candidate whose vertices' box, grown by the radius, holds x.
std::vector<int> near_by_definition(const std::vector<PatchCandidate>& candidates, double radius,
                                    const Vec3& x) {
  std::vector<int> near;
  for (int i = 0; i < int(candidates.size()); ++i) {
    Vec3 lo(1e300), hi(-1e300);
    for (int k = 0; k < candidates[i].vertex_count; ++k) {
      lo = glm::min(lo, candidates[i].vertices[k]);
      hi = glm::max(hi, candidates[i].vertices[k]);
    }
    lo -= Vec3(radius);
    hi += Vec3(radius);
    if (x.x >= lo.x && x.x <= hi.x && x.y >= lo.y && x.y <= hi.y && x.z >= lo.z && x.z <= hi.z)
      near.push_back(i);
  }
  return near;
}

TEST(NearPatches, FindsExactlyThePatchesWhoseGrownBoxHoldsThePoint) {
  // Small and large quads, axis-aligned (one room-like flat floor of many) and tilted; points
  // anywhere, on the grown boxes' faces and corners (the box test includes them), and outside.
  std::mt19937 random(3);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<PatchCandidate> candidates;
  for (int i = 0; i < 100; ++i)
    candidates.push_back(quad({0.1 * (i % 10), 0.1 * (i / 10), 0.0}, {0.1, 0, 0}, {0, 0.1, 0}, i));
  for (int i = 0; i < 200; ++i) {
    const Vec3 o(unit(random), unit(random), unit(random));
    const double size = i % 20 == 0 ? 0.8 : 0.05;
    candidates.push_back(quad(o, size * Vec3(unit(random), unit(random), 0.0),
                              size * Vec3(0.0, unit(random), unit(random)), 100 + i));
  }
  const double radius = 0.004;
  const NearPatches near(candidates, radius);
  std::vector<Vec3> points;
  for (int i = 0; i < 3000; ++i)
    points.push_back(Vec3(1.2 * unit(random) - 0.1, 1.2 * unit(random) - 0.1, 1.2 * unit(random) - 0.1));
  for (int i = 0; i < 1000; ++i)  // near the floor's element corners, within about a radius
    points.push_back(Vec3(0.1 * (i % 11), 0.1 * (i / 11 % 11), 0.0) +
                     radius * Vec3(2 * unit(random) - 1, 2 * unit(random) - 1, 2 * unit(random) - 1));
  for (const PatchCandidate& c : candidates)  // a radius beyond each vertex (the grown box's
                                              // corner, for the largest)
    for (int k = 0; k < c.vertex_count; ++k) points.push_back(c.vertices[k] + Vec3(radius));
  points.push_back(Vec3(5.0, 0.5, 0.5));  // outside everything
  std::size_t found = 0;
  for (const Vec3& x : points) {
    std::vector<int> visited;
    near.for_each_near(x, [&](int position) { visited.push_back(position); });
    ASSERT_EQ(visited, near_by_definition(candidates, radius, x)) << x.x << " " << x.y << " " << x.z;
    found += visited.size();
  }
  EXPECT_GT(found, points.size());  // many points have several near patches
}

TEST(NearPatches, AnEmptySetHasNothingNear) {
  const NearPatches near({}, 1.0);
  int visits = 0;
  near.for_each_near(Vec3(0.0), [&](int) { ++visits; });
  EXPECT_EQ(visits, 0);
}

}  // namespace
}  // namespace ncube

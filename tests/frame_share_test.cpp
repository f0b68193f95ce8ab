// The row-restricted frame of the parallel render (paper section 2.3): parts partition the
// rows, and the frame does not depend on the order the elements arrive in.
#include "render/frame_share.h"

#include <algorithm>
#include <gtest/gtest.h>

#include "render/exposure.h"
#include "render/rasterizer.h"

namespace ncube {
namespace {

TEST(RowShare, PartsCoverEveryRowOnce) {
  for (RowPartition partition : {RowPartition::kBlocks, RowPartition::kScanlines})
    for (int parts : {1, 2, 3, 7, 8, 64})
      for (int height : {1, 16, 47, 600}) {
        std::vector<int> owners(std::size_t(height), 0);
        for (int part = 0; part < parts; ++part) {
          const RowShare share{height, parts, part, partition};
          int count = 0;
          for (int row = share.first_owned_from(0); row < height; row = share.next_owned(row)) {
            ASSERT_TRUE(share.owns(row));
            EXPECT_EQ(share.row_at(share.local_index(row)), row);
            EXPECT_EQ(share.local_index(row), count);
            ++owners[std::size_t(row)];
            ++count;
          }
          EXPECT_EQ(count, share.count());
        }
        for (int row = 0; row < height; ++row) ASSERT_EQ(owners[std::size_t(row)], 1) << row;
      }
  // Blocks are bands of consecutive rows, scanlines every N-th: 47 rows in 4 parts.
  EXPECT_EQ((RowShare{47, 4, 1, RowPartition::kBlocks}.block_begin()), 11);
  EXPECT_EQ((RowShare{47, 4, 1, RowPartition::kBlocks}.count()), 12);
  EXPECT_TRUE((RowShare{47, 4, 1, RowPartition::kScanlines}.owns(45)));
  EXPECT_EQ((RowShare{47, 4, 3, RowPartition::kScanlines}.count()), 11);
}

Camera straight_camera() {
  Camera c;
  c.eye = Vec3(0.0);
  c.look_at = Vec3(0.0, 0.0, -1.0);
  c.up = Vec3(0.0, 1.0, 0.0);
  c.fov_deg = 90.0;
  return c;
}

Patch square(const Vec3& centre, double half, int nu, int nv) {
  Patch p;
  p.polygon = Polygon::quad(centre + Vec3(-half, -half, 0), centre + Vec3(half, -half, 0),
                            centre + Vec3(half, half, 0), centre + Vec3(-half, half, 0));
  p.nu = nu;
  p.nv = nv;
  return p;
}

// Two coplanar, overlapping patches (equal depth everywhere they overlap: every sample
// there is a tie) with different radiosities, and elements sharing edges: drawn in reverse
// order, the frame must still show what scene order shows (the lower element wins a tie).
TEST(FrameShare, ArrivalOrderDoesNotMatter) {
  Scene scene;
  scene.patches = {square(Vec3(0, 0, -5), 1.0, 3, 2), square(Vec3(0.5, 0.3, -5), 1.0, 2, 2)};
  scene.build_elements();
  std::vector<Rgb> radiosity;
  for (std::size_t k = 0; k < scene.elements.size(); ++k)
    radiosity.push_back(k < 6 ? Rgb(1.0, 0.1 * k, 0.0) : Rgb(0.0, 0.1 * k, 1.0));
  std::vector<RenderElement> elements = render_elements(scene, uniform_solution(scene, radiosity), {0, 1});
  const Image sequential = render_solution(scene, straight_camera(), uniform_solution(scene, radiosity), 40, 30);
  std::reverse(elements.begin(), elements.end());
  FrameShare frame(scene, straight_camera(), 40, 30, RowShare::whole(30));
  RenderCounts counts;
  for (const RenderElement& e : elements) frame.draw(e, counts);
  const Image reversed = frame.resolve(frame_exposure(frame), counts);
  EXPECT_EQ(reversed.pixels, sequential.pixels);
  // (Where the two patches overlap, their interpolated depths tie exactly in some samples
  // and differ in the last bit in others: z-fighting, but the same in any order.)
}

// Two identical squares (every depth ties exactly): the first in scene order shows, as when
// the sequential program draws it first and keeps it ("nearer" is strict), whichever arrives
// first.
TEST(FrameShare, DepthTieGoesToTheLowerElement) {
  Scene scene;
  scene.patches = {square(Vec3(0, 0, -5), 1.0, 1, 1), square(Vec3(0, 0, -5), 1.0, 1, 1)};
  scene.build_elements();
  const std::vector<Rgb> radiosity = {Rgb(1.0, 0.0, 0.0), Rgb(0.0, 0.0, 1.0)};
  for (bool reversed : {false, true}) {
    std::vector<RenderElement> elements = render_elements(scene, uniform_solution(scene, radiosity), {0, 1});
    if (reversed) std::reverse(elements.begin(), elements.end());
    FrameShare frame(scene, straight_camera(), 40, 30, RowShare::whole(30));
    RenderCounts counts;
    for (const RenderElement& e : elements) frame.draw(e, counts);
    const Image image = frame.resolve(frame_exposure(frame), counts);
    EXPECT_GT(image.at(20, 15).r, 0.5f) << reversed;
    EXPECT_EQ(image.at(20, 15).b, 0.0f) << reversed;
  }
}

// Counted by hand: a 40 x 30 picture is a 120 x 90 sample frame; with a 90 degree field the
// focal length is 45 samples, so the square of half-size 1 at distance 5 spans samples
// x = 60 + 9X in [51, 69], y = 45 - 9Y in [36, 54]: sample centres 51.5 .. 68.5 and 36.5 ..
// 53.5, an 18 x 18 box for each of its 2 triangles (648 edge tests). All 324 samples lie in
// a triangle, the 18 on the diagonal x + y = 104 in both (inclusive edges): 342 z-tests.
// A quad: 4 corners transformed and projected, none clipped.
TEST(FrameShare, CountsOfOneSquare) {
  Scene scene;
  scene.patches = {square(Vec3(0, 0, -5), 1.0, 1, 1)};
  scene.build_elements();
  FrameShare frame(scene, straight_camera(), 40, 30, RowShare::whole(30));
  RenderCounts counts;
  frame.draw(render_elements(scene, uniform_solution(scene, {Rgb(1.0)}), {0}).front(), counts);
  EXPECT_EQ(counts.vertices, 4u);
  EXPECT_EQ(counts.clip_vertices, 0u);
  EXPECT_EQ(counts.projected_vertices, 4u);
  EXPECT_EQ(counts.triangles, 2u);
  EXPECT_EQ(counts.samples_tested, 648u);
  EXPECT_EQ(counts.samples_inside, 342u);
  EXPECT_GE(counts.samples_written, 324u);  // the diagonal again if its depth rounds nearer
  EXPECT_LE(counts.samples_written, 342u);
  EXPECT_EQ(frame.visible_samples(), 324u);
  // Its rows 12 .. 17 in blocks of 5 rows (6 parts): part 2 (rows 10-14) gets 3 of them,
  // 9 sample rows of 18 samples per triangle.
  FrameShare band(scene, straight_camera(), 40, 30, RowShare{30, 6, 2, RowPartition::kBlocks});
  RenderCounts part;
  band.draw(render_elements(scene, uniform_solution(scene, {Rgb(1.0)}), {0}).front(), part);
  EXPECT_EQ(part.samples_tested, 2u * 9u * 18u);
  EXPECT_EQ(part.triangles, 2u);
}

// A floor from behind the eye to far ahead: two of its edges cross the near plane.
TEST(FrameShare, ClippedVerticesAreCounted) {
  Scene scene;
  Patch floor;
  floor.polygon = Polygon::quad(Vec3(-10, -1, 10), Vec3(10, -1, 10), Vec3(10, -1, -50),
                                Vec3(-10, -1, -50));
  scene.patches = {floor};
  scene.build_elements();
  FrameShare frame(scene, straight_camera(), 40, 30, RowShare::whole(30));
  RenderCounts counts;
  frame.draw(render_elements(scene, uniform_solution(scene, {Rgb(1.0)}), {0}).front(), counts);
  EXPECT_EQ(counts.vertices, 4u);
  EXPECT_EQ(counts.clip_vertices, 2u);
  EXPECT_EQ(counts.projected_vertices, 4u);  // 2 in front + 2 on the near plane
  EXPECT_EQ(counts.triangles, 2u);
}

// Rasterising only some rows counts only their samples: the parts' sample tests add up to
// the whole frame's, for either partition.
TEST(FrameShare, PartsCountTheirOwnRowsOnly) {
  Scene scene;
  scene.patches = {square(Vec3(0, 0, -5), 1.0, 3, 2)};
  scene.build_elements();
  const std::vector<Rgb> radiosity(scene.elements.size(), Rgb(1.0));
  const std::vector<RenderElement> elements = render_elements(scene, uniform_solution(scene, radiosity), {0});
  RenderCounts whole;
  FrameShare all(scene, straight_camera(), 40, 30, RowShare::whole(30));
  for (const RenderElement& e : elements) all.draw(e, whole);
  for (RowPartition partition : {RowPartition::kBlocks, RowPartition::kScanlines}) {
    RenderCounts parts;
    for (int part = 0; part < 4; ++part) {
      FrameShare share(scene, straight_camera(), 40, 30, RowShare{30, 4, part, partition});
      for (const RenderElement& e : elements) share.draw(e, parts);
    }
    EXPECT_EQ(parts.samples_tested, whole.samples_tested);
    EXPECT_EQ(parts.samples_written, whole.samples_written);
    EXPECT_EQ(parts.triangles, 4 * whole.triangles);  // every part sets up every triangle
    // A square of half-size 1 at distance 5 covers 4 x 4 pixels = 12 x 12 samples... plus
    // the inclusive edges of its 6 elements (12 triangles) drawn twice.
    EXPECT_GE(whole.samples_written, 12u * 12u);
  }
  EXPECT_EQ(whole.vertices, 6u * 4u);
  EXPECT_EQ(whole.triangles, 6u * 2u);
}

}  // namespace
}  // namespace ncube

// Which faces of a model stay whole and how the others are cut (src/models/face_shapes.h), as
// the importer gives them: checked on what comes out (the patches' corners), not on how they
// are found, against areas and tolerances worked out by hand (docs/scene-format.md,
// "Importing models").
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "models/model_import.h"

namespace ncube {
namespace {

namespace fs = std::filesystem;
using Corners = std::vector<std::array<double, 3>>;

// The patches' corners of an OBJ of one emitting material whose body is `text`.
std::vector<Corners> imported_patches(const std::string& name, const std::string& text,
                                      ImportSummary& summary) {
  const fs::path dir = fs::path(testing::TempDir()) / ("face_shapes_" + name);
  fs::create_directories(dir);
  std::ofstream(dir / "lamp.mtl") << "newmtl lamp\nKd 0.5 0.5 0.5\nKe 1 1 1\n";
  std::ofstream(dir / "a.obj") << "mtllib lamp.mtl\nusemtl lamp\n" << text;
  const nlohmann::json scene = import_model((dir / "a.obj").string(), {}, summary);
  fs::remove_all(dir);
  std::vector<Corners> patches;
  for (const nlohmann::json& patch : scene["patches"]) patches.push_back(patch["vertices"].get<Corners>());
  return patches;
}

// The z component of the vector area of a polygon in a plane z = const (positive when its
// corners run counter-clockwise seen from +z).
double signed_area_z(const Corners& c) {
  double twice = 0;
  for (std::size_t i = 0; i < c.size(); ++i) {
    const auto& a = c[i];
    const auto& b = c[(i + 1) % c.size()];
    twice += a[0] * b[1] - b[0] * a[1];
  }
  return 0.5 * twice;
}

// The U of the test below: the 3 x 3 square without the notch 1 < x < 2, y > 1.
bool inside_u(double x, double y) {
  const bool square = x > 0 && x < 3 && y > 0 && y < 3;
  const bool notch = x > 1 && x < 2 && y > 1;
  return square && !notch;
}

// A concave face, a U of 8 corners (area 9 - 2 = 7, counter-clockwise seen from +z), whose
// first corner's ear (0,3)-(0,0)-(3,0) holds two other corners and covers part of the notch:
// an ear clipping that does not test for corners inside the ear cuts it there. The pieces
// must cover the U exactly: each facing +z, each inside the U, their areas adding up to 7.
TEST(FaceShapes, AConcaveFaceIsCutIntoPiecesInsideIt) {
  ImportSummary summary;
  const std::vector<Corners> pieces = imported_patches(
      "concave", "v 0 0 0\nv 3 0 0\nv 3 3 0\nv 2 3 0\nv 2 1 0\nv 1 1 0\nv 1 3 0\nv 0 3 0\n"
                 "f 1 2 3 4 5 6 7 8\n", summary);
  EXPECT_EQ(summary.split, 1);
  ASSERT_GE(pieces.size(), 2u);
  double total = 0;
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    const Corners& piece = pieces[k];
    const double area = signed_area_z(piece);
    EXPECT_GT(area, 0.0) << "piece " << k << " faces the other way";
    total += std::fabs(area);
    // Inside: its centroid, and points a tenth of the way from it to each corner and to each
    // edge's midpoint (a triangle that reaches into the notch has one of them there).
    double cx = 0, cy = 0;
    for (const auto& p : piece) {
      cx += p[0] / double(piece.size());
      cy += p[1] / double(piece.size());
    }
    EXPECT_TRUE(inside_u(cx, cy)) << "piece " << k << ": centroid " << cx << ", " << cy;
    for (std::size_t i = 0; i < piece.size(); ++i) {
      const auto& a = piece[i];
      const auto& b = piece[(i + 1) % piece.size()];
      const double mx = 0.5 * (a[0] + b[0]), my = 0.5 * (a[1] + b[1]);
      EXPECT_TRUE(inside_u(0.9 * a[0] + 0.1 * cx, 0.9 * a[1] + 0.1 * cy)) << "piece " << k << " corner " << i;
      EXPECT_TRUE(inside_u(0.9 * mx + 0.1 * cx, 0.9 * my + 0.1 * cy)) << "piece " << k << " edge " << i;
    }
  }
  EXPECT_NEAR(total, 7.0, 1e-12);
}

// A quad stays one patch when its fourth corner is within 1e-7 of its diameter of the plane of
// the first three (docs/scene-format.md). The unit square with its fourth corner raised by h
// has diameter sqrt(2 + h^2), so the tolerance is 1.414e-7: h = 1.3e-7 is kept whole,
// h = 1.5e-7 (6 % outside) is cut into two triangles along the diagonal from corner 0.
TEST(FaceShapes, ANearlyPlanarQuadJustOutsideTheToleranceIsCut) {
  ImportSummary kept_summary, cut_summary;
  const std::vector<Corners> kept = imported_patches(
      "kept", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 1.3e-7\nf 1 2 3 4\n", kept_summary);
  ASSERT_EQ(kept.size(), 1u);
  EXPECT_EQ(kept[0].size(), 4u);
  EXPECT_EQ(kept_summary.split, 0);
  const std::vector<Corners> cut = imported_patches(
      "cut", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 1.5e-7\nf 1 2 3 4\n", cut_summary);
  EXPECT_EQ(cut_summary.split, 1);
  ASSERT_EQ(cut.size(), 2u);
  EXPECT_EQ(cut[0], (Corners{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}));
  EXPECT_EQ(cut[1], (Corners{{1, 1, 0}, {0, 1, 1.5e-7}, {0, 0, 0}}));
}

}  // namespace
}  // namespace ncube

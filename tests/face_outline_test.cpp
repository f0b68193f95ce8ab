// Faces' outlines (src/models/face_shapes.h, model_import.h): a self-intersecting outline is
// refused naming the face and the two edges that cross; a simple star of the same corners is
// cut into triangles that cover its area, worked out from the star's radii; faces over the
// corner limit are refused.
#include "models/face_shapes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "models/model_import.h"
#include "util/input_error.h"

namespace ncube {
namespace {

namespace fs = std::filesystem;
using models::Point;

// Corner k of 5 on the unit circle, the first at the top.
Point outer(int k) { return {std::cos(M_PI / 2 + 2 * M_PI * k / 5), std::sin(M_PI / 2 + 2 * M_PI * k / 5), 0}; }
// The star's inner corners: where the pentagram's edges cross, at radius cos 72 / cos 36.
Point inner(int k) {
  const double r = std::cos(2 * M_PI / 5) / std::cos(M_PI / 5);
  const double a = M_PI / 2 + 2 * M_PI * k / 5 + M_PI / 5;
  return {r * std::cos(a), r * std::sin(a), 0};
}

double triangle_area(const std::vector<Point>& t) {
  const Point e = t[1] - t[0], f = t[2] - t[0];
  return 0.5 * (e.x * f.y - e.y * f.x);  // signed, seen from +z
}

TEST(FaceOutline, PentagramEdgesCross) {
  // Corners 0, 2, 4, 1, 3 of the pentagon: its first edge (top to lower left) crosses its
  // third (upper right to upper left, the horizontal at y = sin 18), the first pair found.
  const std::vector<Point> pentagram{outer(0), outer(2), outer(4), outer(1), outer(3)};
  const auto crossing = models::crossing_edges(pentagram);
  ASSERT_TRUE(crossing.has_value());
  EXPECT_EQ(crossing->first, 0u);
  EXPECT_EQ(crossing->second, 2u);
  // A bow-tie quad (not symmetric: one of net area zero has no plane and is dropped as flat).
  EXPECT_TRUE(models::crossing_edges({{0, 0, 0}, {2, 2, 0}, {2, 0, 0}, {0, 1, 0}}).has_value());
  // The pentagon itself, and a concave L, do not cross.
  EXPECT_FALSE(models::crossing_edges({outer(0), outer(1), outer(2), outer(3), outer(4)}).has_value());
  EXPECT_FALSE(models::crossing_edges({{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}})
                   .has_value());
}

TEST(FaceOutline, SimpleStarIsCutIntoItsArea) {
  std::vector<Point> star;
  for (int k = 0; k < 5; ++k) {
    star.push_back(outer(k));
    star.push_back(inner(k));
  }
  ASSERT_FALSE(models::crossing_edges(star).has_value());
  // The star is 10 triangles (centre, outer corner, inner corner) of area r sin 36 / 2.
  const double r = std::cos(2 * M_PI / 5) / std::cos(M_PI / 5);
  const double expected = 5 * r * std::sin(M_PI / 5);  // 1.1226
  const auto triangles = models::split(star);
  ASSERT_EQ(triangles.size(), 8u);
  double total = 0.0;
  for (const auto& t : triangles) {
    EXPECT_GT(triangle_area(t), 0.0);  // every piece faces the star's way: no overlap
    total += triangle_area(t);
  }
  EXPECT_NEAR(total, expected, 1e-12);
  EXPECT_NEAR(expected, 1.1226, 1e-4);
}

// A C: the ear at corner 0, (0,3)-(0,0)-(3,0), would hold the notch's corners (1,1) and (1,2):
// cut there, the triangles would overlap and cover the notch. The C is 3 x 3 less the 2 x 1
// notch, area 7, cut into 6 triangles that all face its way.
TEST(FaceOutline, ConcaveFaceIsCutWithoutOverlap) {
  const std::vector<Point> c{{0, 0, 0}, {3, 0, 0}, {3, 1, 0}, {1, 1, 0},
                             {1, 2, 0}, {3, 2, 0}, {3, 3, 0}, {0, 3, 0}};
  const auto triangles = models::split(c);
  ASSERT_EQ(triangles.size(), 6u);
  double total = 0.0;
  for (const auto& t : triangles) {
    EXPECT_GT(triangle_area(t), 0.0);
    total += std::fabs(triangle_area(t));
  }
  EXPECT_DOUBLE_EQ(total, 7.0);
}

struct FaceOutlineFile : testing::Test {
  fs::path dir;
  void SetUp() override {
    dir = fs::path(testing::TempDir()) /
          ("face_outline_file_" + std::string(testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::create_directories(dir);
    std::ofstream(dir / "m.mtl") << "newmtl lamp\nKd 0.5 0.5 0.5\nKe 1 1 1\n";
  }
  void TearDown() override { fs::remove_all(dir); }
  // An OBJ of one face through the corners given, in the order `face` lists them (1-based).
  std::string write(const std::vector<Point>& corners, const std::string& face) {
    std::ofstream out(dir / "a.obj");
    out.precision(17);
    out << "mtllib m.mtl\no star\n";
    for (const Point& p : corners) out << "v " << p.x << " " << p.y << " " << p.z << "\n";
    out << "usemtl lamp\nf " << face << "\n";
    return (dir / "a.obj").string();
  }
  std::string refusal(const std::string& path) {
    ImportSummary summary;
    try {
      import_model(path, {}, summary);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
};

TEST_F(FaceOutlineFile, PentagramIsRefusedNamingTheFace) {
  const std::string path = write({outer(0), outer(1), outer(2), outer(3), outer(4)}, "1 3 5 2 4");
  EXPECT_EQ(refusal(path), path + ": mesh 0 \"star\", material \"lamp\", face 0: self-intersecting "
                                  "face: its edges between corners 0-1 and 2-3 cross (corners "
                                  "counted from 0; split it into simple polygons)");
}

// A bow-tie of two equal halves has no net area, so no plane to find crossings in; its corners
// span the plane z = 0 (each half 1/4): refused, where a face of collinear corners is dropped.
TEST_F(FaceOutlineFile, SymmetricBowTieIsRefusedAndALineDropped) {
  const std::string path = write({{0, 0, 0}, {1, 1, 0}, {1, 0, 0}, {0, 1, 0}}, "1 2 3 4");
  EXPECT_EQ(refusal(path), path + ": mesh 0 \"star\", material \"lamp\", face 0: self-intersecting "
                                  "face: its 4 corners span a plane but enclose no net area (a "
                                  "bow-tie of two equal halves; split it into simple polygons)");
  std::ofstream(dir / "b.obj") << "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\nv 3 0 0\n"
                                  "usemtl lamp\nf 1 2 3\nf 1 2 4 5\n";
  ImportSummary summary;
  import_model((dir / "b.obj").string(), {}, summary);
  EXPECT_EQ(summary.degenerate, 1);  // the four corners on a line
  EXPECT_EQ(summary.patches, 1);
}

TEST_F(FaceOutlineFile, SimpleStarImportsWithItsArea) {
  std::vector<Point> star;
  std::string face;
  for (int k = 0; k < 5; ++k) {
    star.push_back(outer(k));
    star.push_back(inner(k));
    face += std::to_string(2 * k + 1) + " " + std::to_string(2 * k + 2) + " ";
  }
  ImportSummary summary;
  const nlohmann::json scene = import_model(write(star, face), {}, summary);
  double total = 0.0;
  for (const nlohmann::json& patch : scene["patches"]) {
    std::vector<Point> t;
    for (const nlohmann::json& v : patch["vertices"]) t.push_back({v[0], v[1], v[2]});
    total += triangle_area(t);
  }
  EXPECT_EQ(summary.patches, 8);
  // The OBJ's coordinates are read as floats: the area to their precision.
  EXPECT_NEAR(total, 5 * std::cos(2 * M_PI / 5) / std::cos(M_PI / 5) * std::sin(M_PI / 5), 1e-6);
}

// A regular polygon of n corners has area n sin(2 pi / n) / 2; 32,767 corners are cut, 32,768 refused (by
// Assimp's own limit, the same number: its message, naming the file and the face).
TEST_F(FaceOutlineFile, CornerLimit) {
  for (unsigned n : {models::kMaxFaceCorners, models::kMaxFaceCorners + 1}) {
    std::vector<Point> ring;
    std::string face;
    for (unsigned k = 0; k < n; ++k) {
      ring.push_back({std::cos(2 * M_PI * k / n), std::sin(2 * M_PI * k / n), 0});
      face += std::to_string(k + 1) + " ";
    }
    const std::string path = write(ring, face);
    if (n == models::kMaxFaceCorners) {
      ImportSummary summary;
      const nlohmann::json scene = import_model(path, {}, summary);
      double total = 0.0;
      for (const nlohmann::json& patch : scene["patches"]) {
        std::vector<Point> t;
        for (const nlohmann::json& v : patch["vertices"]) t.push_back({v[0], v[1], v[2]});
        total += triangle_area(t);
      }
      // n - 2 triangles, but for the odd one that the OBJ's float coordinates make flat
      // (corners 2e-4 apart on the circle, 6e-8 float steps), dropped as degenerate.
      EXPECT_LE(summary.patches, long(n) - 2);
      EXPECT_GE(summary.patches, long(n) - 4);
      EXPECT_NEAR(total, n * std::sin(2 * M_PI / n) / 2, 1e-5);
    } else {
      EXPECT_EQ(refusal(path), path + ": cannot read the model: Validation failed: Face 0 has too many "
                                      "faces: 32768, but the limit is 32767");
    }
  }
}

}  // namespace
}  // namespace ncube

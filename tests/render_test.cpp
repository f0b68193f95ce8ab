#include <png.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "render/exposure.h"
#include "render/frame_share.h"
#include "render/image.h"
#include "render/rasterizer.h"
#include "util/input_error.h"

namespace ncube {
namespace {

// Camera at the origin looking down -z with a 90 degree field: a point (x, y, -d) lands at
// pixel (W/2 + (H/2) x/d, H/2 - (H/2) y/d).
Camera straight_camera() {
  Camera c;
  c.eye = Vec3(0.0);
  c.look_at = Vec3(0.0, 0.0, -1.0);
  c.up = Vec3(0.0, 1.0, 0.0);
  c.fov_deg = 90.0;
  return c;
}

// An axis-aligned square facing +z (towards the camera), centred at `centre`.
Patch square(const Vec3& centre, double half, int nu = 1, int nv = 1) {
  Patch p;
  p.polygon = Polygon::quad(centre + Vec3(-half, -half, 0), centre + Vec3(half, -half, 0),
                            centre + Vec3(half, half, 0), centre + Vec3(-half, half, 0));
  p.nu = nu;
  p.nv = nv;
  return p;
}

bool lit(const Image& image, int x, int y) {
  const glm::vec3& p = image.at(x, y);
  return p.r + p.g + p.b > 0.0f;
}

TEST(Render, SquareFillsItsProjection) {
  Scene scene;
  scene.patches = {square(Vec3(0, 0, -5), 1.0)};
  scene.build_elements();
  // Half-size 1 at distance 5 covers 50 +- 10 pixels.
  const Image image = render_solution(scene, straight_camera(), uniform_solution(scene, {Rgb(1.0)}), 100, 100);
  ASSERT_EQ(image.width, 100);
  ASSERT_EQ(image.height, 100);
  EXPECT_TRUE(lit(image, 50, 50));
  EXPECT_TRUE(lit(image, 41, 58));
  EXPECT_FALSE(lit(image, 38, 50));
  EXPECT_FALSE(lit(image, 50, 61));
  EXPECT_FALSE(lit(image, 0, 0));
  EXPECT_FALSE(lit(image, 99, 99));
  // A constant surface is exposed to 0.9 linear, i.e. sRGB ~0.95, grey.
  EXPECT_NEAR(image.at(50, 50).g, 0.9546f, 2e-3f);
  EXPECT_EQ(image.at(50, 50).r, image.at(50, 50).b);
}

TEST(Render, ProjectionIsThePinholeFormula) {
  const Camera camera = straight_camera();
  const Vec3 point(1.0, 0.5, -4.0);
  const auto p = project(camera, 100, 100, point);
  ASSERT_TRUE(p.has_value());
  EXPECT_NEAR(p->x, 50.0 + 50.0 * 1.0 / 4.0, 1e-9);  // 62.5
  EXPECT_NEAR(p->y, 50.0 - 50.0 * 0.5 / 4.0, 1e-9);  // 43.75
  EXPECT_FALSE(project(camera, 100, 100, Vec3(0.0, 0.0, 1.0)).has_value());

  // A small square around the point lights that pixel and not the centre.
  Scene scene;
  scene.patches = {square(point, 0.2)};
  scene.build_elements();
  const Image image = render_solution(scene, camera, uniform_solution(scene, {Rgb(1.0)}), 100, 100);
  EXPECT_TRUE(lit(image, 62, 43));
  EXPECT_FALSE(lit(image, 50, 50));
}

TEST(Render, GouraudRampAcrossTwoElements) {
  Scene scene;
  scene.patches = {square(Vec3(0, 0, -5), 1.0, 2, 1)};
  scene.build_elements();
  // Vertex radiosities along x: 0, mean(0, 1), 1: a linear ramp over pixels 40..59.
  const Image image = render_solution(scene, straight_camera(), uniform_solution(scene, {Rgb(0.0), Rgb(1.0)}), 100, 100);
  for (int x = 41; x < 59; ++x) EXPECT_LT(image.at(x, 50).g, image.at(x + 1, 50).g) << x;
  EXPECT_LT(image.at(41, 50).g, 0.3f);
  EXPECT_GT(image.at(58, 50).g, 0.8f);
}

TEST(Render, NearerSquareOccludesFartherInEitherOrder) {
  for (bool near_first : {true, false}) {
    Scene scene;
    const Patch near = square(Vec3(0, 0, -3), 0.3), far = square(Vec3(0, 0, -6), 3.0);
    scene.patches = near_first ? std::vector<Patch>{near, far} : std::vector<Patch>{far, near};
    scene.build_elements();
    const Rgb red(1, 0, 0), green(0, 1, 0);
    const std::vector<Rgb> radiosity = near_first ? std::vector<Rgb>{red, green}
                                                  : std::vector<Rgb>{green, red};
    const Image image = render_solution(scene, straight_camera(), uniform_solution(scene, radiosity), 100, 100);
    EXPECT_GT(image.at(50, 50).r, 0.5f);  // near square: covers 50 +- 5
    EXPECT_EQ(image.at(50, 50).g, 0.0f);
    EXPECT_GT(image.at(50, 30).g, 0.5f);  // only the far square
    EXPECT_EQ(image.at(50, 30).r, 0.0f);
  }
}

TEST(Render, BackFacesAreDrawn) {
  Scene scene;
  Patch p = square(Vec3(0, 0, -5), 1.0);
  std::swap(p.polygon.vertices[1], p.polygon.vertices[3]);  // now faces away
  scene.patches = {p};
  scene.build_elements();
  EXPECT_TRUE(lit(render_solution(scene, straight_camera(), uniform_solution(scene, {Rgb(1.0)}), 100, 100), 50, 50));
}

TEST(Render, NearPlaneClipsPolygonsBehindTheEye) {
  // A floor running from behind the eye to far ahead: its visible part is the lower half.
  Scene scene;
  Patch floor;
  floor.polygon = Polygon::quad(Vec3(-10, -1, 10), Vec3(10, -1, 10), Vec3(10, -1, -50),
                                Vec3(-10, -1, -50));
  scene.patches = {floor};
  scene.build_elements();
  const Image image = render_solution(scene, straight_camera(), uniform_solution(scene, {Rgb(1.0)}), 100, 100);
  EXPECT_TRUE(lit(image, 50, 99));
  EXPECT_TRUE(lit(image, 50, 52));
  EXPECT_FALSE(lit(image, 50, 45));
}

TEST(Render, TriangleCellsShareTheApex) {
  Scene scene;
  Patch p;
  p.polygon = Polygon::triangle(Vec3(-1, -1, -5), Vec3(1, -1, -5), Vec3(0, 1, -5));
  p.nu = 2;
  p.nv = 2;
  scene.patches = {p};
  scene.build_elements();
  ASSERT_EQ(scene.elements.size(), 4u);
  const Image image = render_solution(scene, straight_camera(), uniform_solution(scene, {Rgb(1.0), Rgb(1.0), Rgb(1.0), Rgb(1.0)}), 100, 100);
  EXPECT_TRUE(lit(image, 50, 45));
  EXPECT_NEAR(image.at(50, 45).g, image.at(50, 58).g, 1e-6f);  // constant stays constant
}

TEST(Render, IsDeterministic) {
  Scene scene;
  scene.patches = {square(Vec3(0.1, 0.2, -5), 1.0, 3, 2), square(Vec3(0, 0, -7), 3.0)};
  scene.patches[1].emission = Rgb(5.0);
  scene.build_elements();
  std::vector<Rgb> radiosity;
  for (std::size_t k = 0; k < scene.elements.size(); ++k) radiosity.push_back(Rgb(0.1 * k));
  const Image a = render_solution(scene, straight_camera(), uniform_solution(scene, radiosity), 64, 48);
  const Image b = render_solution(scene, straight_camera(), uniform_solution(scene, radiosity), 64, 48);
  EXPECT_EQ(a.pixels, b.pixels);
}

TEST(Render, RejectsBadInput) {
  Scene scene;
  scene.patches = {square(Vec3(0, 0, -5), 1.0)};
  scene.build_elements();
  EXPECT_THROW(render_solution(scene, straight_camera(), uniform_solution(scene, {}), 10, 10), InputError);
  Camera camera = straight_camera();
  camera.look_at = camera.eye;
  EXPECT_THROW(render_solution(scene, camera, uniform_solution(scene, {Rgb(1.0)}), 10, 10), InputError);
}

// ------------------------------------------------ the adaptive mesh (section 4.1)

// A 2 x 1 patch (x in [-1, 1], y in [-1, 1] at distance 5: pixels 40..59 of a 100 x 100
// picture) whose left element is cut once, and the child next to the right (level-0)
// element cut again: the right element's left edge carries T-vertices at a quarter and at
// half its height.
const std::vector<ElementCell> kMixedCells = {
    {1, 0, 0}, {2, 2, 0}, {2, 3, 0}, {2, 2, 1}, {2, 3, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 0}};

Scene mixed_patch_scene(const Vec3& centre = Vec3(0, 0, -5)) {
  Scene scene;
  scene.patches = {square(centre, 1.0, 2, 1)};
  scene.build_elements();
  return scene;
}

std::vector<PatchSolution> solution_of(const std::vector<ElementCell>& cells,
                                       const std::vector<Rgb>& radiosity) {
  return {PatchSolution{0, cells, radiosity}};
}

TEST(RenderAdaptiveMesh, SubdividedPatchOfOneRadiosityIsTheUnsubdividedPicture) {
  const Scene scene = mixed_patch_scene();
  const Image level0 =
      render_solution(scene, straight_camera(), uniform_solution(scene, {Rgb(0.7), Rgb(0.7)}), 100, 100);
  // Once: the left element in four; twice: one of those in four again, next to the level-0
  // element.
  const std::vector<ElementCell> once = {{1, 0, 0}, {1, 1, 0}, {1, 0, 1}, {1, 1, 1}, {0, 1, 0}};
  for (const std::vector<ElementCell>& cells : {once, kMixedCells}) {
    const Image image = render_solution(scene, straight_camera(),
                                        solution_of(cells, std::vector<Rgb>(cells.size(), Rgb(0.7))),
                                        100, 100);
    int lit_pixels = 0;
    for (int y = 0; y < 100; ++y)
      for (int x = 0; x < 100; ++x) {
        ASSERT_EQ(lit(image, x, y), lit(level0, x, y)) << x << ", " << y << " (" << cells.size() << " cells)";
        lit_pixels += lit(image, x, y);
      }
    EXPECT_EQ(lit_pixels, 20 * 20);
    EXPECT_EQ(encode_png(image), encode_png(level0)) << cells.size() << " cells";
  }
}

// The records of a solution with only their corners, each with its nodal radiosity: what a
// renderer that ignores T-vertices draws.
std::vector<RenderElement> corners_only(const Scene& scene, const std::vector<PatchSolution>& solution) {
  std::vector<RenderElement> records = render_elements(scene, solution, {0});
  const PatchMesh mesh(scene.patches[0], solution[0].cells);
  for (std::size_t k = 0; k < records.size(); ++k) {
    const Polygon polygon = cell_polygon(scene.patches[0], solution[0].cells[k]);
    records[k].boundary.clear();
    for (int c = 0; c < mesh.corner_count(k); ++c)
      records[k].boundary.push_back({polygon[c], mesh.corner_radiosity(solution[0].radiosity, k, c)});
  }
  return records;
}

double srgb_decode(float c) {
  return c <= 0.04045f ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

// The largest jump, in radiosity units, of the shading across the T-junction edge x = 0
// (between pixels 49 and 50), over the rows the patch covers: the step across the edge less
// the mean of the steps beside it (49 - 48 and 51 - 50), which removes the surface's slope.
double seam_across_the_t_junction_edge(const Scene& scene, const std::vector<RenderElement>& records) {
  FrameShare frame(scene, straight_camera(), 100, 100, RowShare::whole(100));
  RenderCounts counts;
  for (const RenderElement& r : records) frame.draw(r, counts);
  const double scale = frame_exposure(frame);
  const Image image = frame.resolve(scale, counts);
  double seam = 0.0;
  for (int y = 41; y < 59; ++y) {
    const auto B = [&](int x) {
      EXPECT_LT(image.at(x, y).g, 0.99f) << "clamped: the pixel no longer tells the radiosity";
      return srgb_decode(image.at(x, y).g) / scale;
    };
    const double across = B(50) - B(49), left = B(49) - B(48), right = B(51) - B(50);
    seam = std::max(seam, std::abs(across - 0.5 * (left + right)));
  }
  return seam;
}

// A radiosity ramp along the T-junction edge, B = 1 + v (v from 0 at the bottom to 1 at the
// top of the patch: 20 pixel rows, 0.05 per row), each element at its centre's value. A
// continuous surface leaves in the jump estimate only its kinks (fan spokes, T-vertex rows)
// within the three pixels: under half a row's worth of ramp (measured 0.016). A renderer that
// drew the right element with its 4 corners only interpolates past the T-vertices, whose
// nodal radiosities the small elements show: a jump of up to 0.07 (about 1.4 rows' worth).
TEST(RenderAdaptiveMesh, NoSeamAlongATJunctionEdge) {
  const Scene scene = mixed_patch_scene();
  std::vector<Rgb> radiosity;
  for (const ElementCell& c : kMixedCells) {
    const double rows = double(1 << c.level);  // cells along v at this level (nv = 1)
    radiosity.push_back(Rgb(1.0 + (c.j + 0.5) / rows));
  }
  const std::vector<PatchSolution> solution = solution_of(kMixedCells, radiosity);
  const double tolerance = 0.5 * (1.0 / 20.0);
  const double whole = seam_across_the_t_junction_edge(scene, render_elements(scene, solution, {0}));
  EXPECT_LT(whole, tolerance);
  const double corners = seam_across_the_t_junction_edge(scene, corners_only(scene, solution));
  EXPECT_GT(corners, tolerance) << "the test must see the seam of 4-corner records";
}

// Outlines: with an offset that puts no sample centre at half a sample from an edge, the
// dark samples are exactly those inside the patch within half a sample of an element edge:
// with a straight camera at distance 5, x_sample = 150 + 30 X and y_sample = 150 - 30 Y.
// Every other pixel is the picture without outlines, fan diagonals included.
TEST(RenderAdaptiveMesh, OutlinesFollowElementEdgesNotFanDiagonals) {
  const double dx = 0.013, dy = 0.021;
  const Scene scene = mixed_patch_scene(Vec3(dx, dy, -5));
  const std::vector<ElementCell> cells = {{1, 0, 0}, {1, 1, 0}, {1, 0, 1}, {1, 1, 1}, {0, 1, 0}};
  const std::vector<PatchSolution> solution = solution_of(cells, std::vector<Rgb>(cells.size(), Rgb(1.0)));
  const Image plain = render_solution(scene, straight_camera(), solution, 100, 100);
  const Image outlined = render_solution(scene, straight_camera(), solution, 100, 100, true);
  // Element edges: x = -1, -0.5, 0, 1 over the whole height; y = -1, 1 over the whole width,
  // y = 0 over the left half (the children); all shifted by (dx, dy).
  const auto near = [](double sample, double edge) { return std::abs(sample - edge) <= 0.5; };
  const auto outline_sample = [&](double sx, double sy) {
    const double X = (sx - 150.0) / 30.0 - dx, Y = (150.0 - sy) / 30.0 - dy;
    if (std::abs(X) > 1.0 || std::abs(Y) > 1.0) return false;  // background
    for (double e : {-1.0, -0.5, 0.0, 1.0})
      if (near(sx, 150.0 + 30.0 * (e + dx))) return true;
    for (double e : {-1.0, 1.0})
      if (near(sy, 150.0 - 30.0 * (e + dy))) return true;
    return X <= 0.0 && near(sy, 150.0 - 30.0 * dy);
  };
  int outlined_pixels = 0;
  for (int y = 0; y < 100; ++y)
    for (int x = 0; x < 100; ++x) {
      int dark = 0;
      for (int sy = 0; sy < 3; ++sy)
        for (int sx = 0; sx < 3; ++sx) dark += outline_sample(3 * x + sx + 0.5, 3 * y + sy + 0.5);
      if (dark == 0) {
        ASSERT_EQ(outlined.at(x, y), plain.at(x, y)) << x << ", " << y;
      } else {
        ASSERT_LT(outlined.at(x, y).g, plain.at(x, y).g) << x << ", " << y;
        ++outlined_pixels;
      }
    }
  EXPECT_GT(outlined_pixels, 60);
  // By hand: the T-junction edge x = 0 (sample x 150.39: pixel 50) and the children's edges
  // x = -0.5 (pixel 45) and y = 0 in the left half (sample y 149.37: row 49) are outlined;
  // row 49 in the right element (no edge there) and the diagonals are not.
  for (int y = 41; y < 59; ++y) {
    EXPECT_LT(outlined.at(50, y).g, plain.at(50, y).g) << y;
    EXPECT_LT(outlined.at(45, y).g, plain.at(45, y).g) << y;
  }
  for (int x = 41; x < 49; ++x) EXPECT_LT(outlined.at(x, 49).g, plain.at(x, 49).g) << x;
  for (int x = 52; x < 59; ++x) EXPECT_EQ(outlined.at(x, 49), plain.at(x, 49)) << x;
  EXPECT_EQ(outlined.at(42, 55), plain.at(42, 55));  // child (0, 0)'s fan diagonal
  EXPECT_EQ(outlined.at(56, 45), plain.at(56, 45));  // a spoke of the right element's fan
}

TEST(WritePng, ReadsBackWithLibpng) {
  Image image(7, 5);
  image.at(3, 2) = glm::vec3(1.0f, 0.5f, 0.0f);
  const std::string path = testing::TempDir() + "render_test_" + std::to_string(getpid()) + ".png";
  write_png(image, path);

  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  ASSERT_NE(png_image_begin_read_from_file(&png, path.c_str()), 0) << png.message;
  EXPECT_EQ(png.width, 7u);
  EXPECT_EQ(png.height, 5u);
  png.format = PNG_FORMAT_RGB;
  std::vector<unsigned char> bytes(PNG_IMAGE_SIZE(png));
  ASSERT_NE(png_image_finish_read(&png, nullptr, bytes.data(), 0, nullptr), 0) << png.message;
  const std::size_t k = 3 * (2 * 7 + 3);
  EXPECT_EQ(bytes[k], 255);
  EXPECT_EQ(bytes[k + 1], 128);
  EXPECT_EQ(bytes[k + 2], 0);
  EXPECT_EQ(bytes[0], 0);
  std::remove(path.c_str());
  EXPECT_NE(access((path + ".tmp").c_str(), F_OK), 0);
}

TEST(WritePng, UnwritablePathThrowsAndLeavesNoFile) {
  const std::string path = "/nonexistent/dir/x.png";
  try {
    write_png(Image(4, 4), path);
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos);
  }
  EXPECT_NE(access(path.c_str(), F_OK), 0);
  EXPECT_NE(access((path + ".tmp").c_str(), F_OK), 0);
}

// solution_exposure draws the picture in bands of rows: its exposure is the whole frame's,
// exactly (the same visible samples), with non-emitters in view and with emitters alone.
TEST(Render, BandedExposureIsTheWholeFramesExposure) {
  Scene scene;
  scene.patches = {square(Vec3(0, 0, -5), 1.0, 3, 3), square(Vec3(0.8, 0.5, -4), 0.6, 2, 2),
                   square(Vec3(-0.5, -0.9, -6), 1.5, 4, 1), square(Vec3(0.2, 1.4, -3), 0.3)};
  scene.patches[1].emission = Rgb(4.0);
  scene.build_elements();
  std::vector<Rgb> radiosity;   // a different radiosity for every element
  for (std::size_t k = 0; k < scene.elements.size(); ++k)
    radiosity.push_back(Rgb(4.0 / double(1 + k), 0.2 * double(k % 5), 0.1 + 0.05 * double(k)));
  const std::vector<PatchSolution> solution = uniform_solution(scene, radiosity);
  const auto whole = [&](const Scene& sc, const std::vector<PatchSolution>& sol, int w, int h) {
    FrameShare frame(sc, straight_camera(), w, h, RowShare::whole(h));
    RenderCounts counts;
    std::vector<int> all(sc.patches.size());
    for (std::size_t p = 0; p < all.size(); ++p) all[p] = int(p);
    for (const RenderElement& e : render_elements(sc, sol, all)) frame.draw(e, counts);
    return frame_exposure(frame);
  };
  for (const auto& [w, h] : {std::pair{100, 150}, std::pair{37, 64}, std::pair{50, 65}})
    EXPECT_EQ(solution_exposure(scene, straight_camera(), solution, w, h), whole(scene, solution, w, h))
        << w << " x " << h;
  // Emitters alone in view: the exposure comes from all visible samples.
  for (Patch& patch : scene.patches) patch.emission = Rgb(2.0);
  scene.build_elements();
  EXPECT_EQ(solution_exposure(scene, straight_camera(), solution, 100, 150),
            whole(scene, solution, 100, 150));
}

}  // namespace
}  // namespace ncube

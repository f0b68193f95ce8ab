#include <png.h>
#include <unistd.h>

#include <cstdio>
#include <string>

#include <gtest/gtest.h>

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
  const Image image = render_solution(scene, straight_camera(), {Rgb(1.0)}, 100, 100);
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
  const Image image = render_solution(scene, camera, {Rgb(1.0)}, 100, 100);
  EXPECT_TRUE(lit(image, 62, 43));
  EXPECT_FALSE(lit(image, 50, 50));
}

TEST(Render, GouraudRampAcrossTwoElements) {
  Scene scene;
  scene.patches = {square(Vec3(0, 0, -5), 1.0, 2, 1)};
  scene.build_elements();
  // Vertex radiosities along x: 0, mean(0, 1), 1: a linear ramp over pixels 40..59.
  const Image image = render_solution(scene, straight_camera(), {Rgb(0.0), Rgb(1.0)}, 100, 100);
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
    const Image image = render_solution(scene, straight_camera(), radiosity, 100, 100);
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
  EXPECT_TRUE(lit(render_solution(scene, straight_camera(), {Rgb(1.0)}, 100, 100), 50, 50));
}

TEST(Render, NearPlaneClipsPolygonsBehindTheEye) {
  // A floor running from behind the eye to far ahead: its visible part is the lower half.
  Scene scene;
  Patch floor;
  floor.polygon = Polygon::quad(Vec3(-10, -1, 10), Vec3(10, -1, 10), Vec3(10, -1, -50),
                                Vec3(-10, -1, -50));
  scene.patches = {floor};
  scene.build_elements();
  const Image image = render_solution(scene, straight_camera(), {Rgb(1.0)}, 100, 100);
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
  const Image image = render_solution(scene, straight_camera(),
                                      {Rgb(1.0), Rgb(1.0), Rgb(1.0), Rgb(1.0)}, 100, 100);
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
  const Image a = render_solution(scene, straight_camera(), radiosity, 64, 48);
  const Image b = render_solution(scene, straight_camera(), radiosity, 64, 48);
  EXPECT_EQ(a.pixels, b.pixels);
}

TEST(Render, RejectsBadInput) {
  Scene scene;
  scene.patches = {square(Vec3(0, 0, -5), 1.0)};
  scene.build_elements();
  EXPECT_THROW(render_solution(scene, straight_camera(), {}, 10, 10), InputError);
  Camera camera = straight_camera();
  camera.look_at = camera.eye;
  EXPECT_THROW(render_solution(scene, camera, {Rgb(1.0)}, 10, 10), InputError);
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

}  // namespace
}  // namespace ncube

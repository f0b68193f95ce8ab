// Models in (src/models/model_import.h): a hand-written OBJ + MTL whose patches, areas,
// reflectances and emission were worked out by hand (tests/models/room.obj), the Cornell box
// written as OBJ from the published data against scenes/cornell-box.json, the same model as
// glTF, and bad files, each refused with one message.
#include "models/model_import.h"

#include <assimp/Exporter.hpp>
#include <assimp/Importer.hpp>
#include <assimp/scene.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "util/input_error.h"

namespace ncube {
namespace {

namespace fs = std::filesystem;

std::string model(const std::string& name) {
  return std::string(NCUBE_SOURCE_DIR) + "/tests/models/" + name;
}

double area(const nlohmann::json& patch) {
  const auto v = [&patch](std::size_t k, int c) { return patch["vertices"][k][std::size_t(c)].get<double>(); };
  double n[3] = {0, 0, 0};
  const std::size_t count = patch["vertices"].size();
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t j = (i + 1) % count;
    n[0] += (v(i, 1) - v(j, 1)) * (v(i, 2) + v(j, 2));
    n[1] += (v(i, 2) - v(j, 2)) * (v(i, 0) + v(j, 0));
    n[2] += (v(i, 0) - v(j, 0)) * (v(i, 1) + v(j, 1));
  }
  return 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
}

TEST(ModelImport, ReadsTheHandWrittenRoom) {
  ImportSummary summary;
  const nlohmann::json scene = import_model(model("room.obj"), {}, summary);
  // 7 faces: 4 quads kept (light, floor, wall; the quad with a repeated corner is a triangle),
  // the bent quad cut in 2, the pentagon in 3, the flat triangle dropped.
  EXPECT_EQ(summary.faces, 7);
  EXPECT_EQ(summary.split, 2);
  EXPECT_EQ(summary.degenerate, 1);
  ASSERT_EQ(summary.patches, 9);
  const nlohmann::json& p = scene["patches"];
  ASSERT_EQ(p.size(), 9u);
  const double areas[] = {1, 1, 2, 0, 0, 0.5, 0.5, 0.25, 0.5};
  for (std::size_t k : {0u, 1u, 2u, 5u, 6u, 7u, 8u}) EXPECT_NEAR(area(p[k]), areas[k], 1e-12) << k;
  // The bent quad's halves: cut along its diagonal from corner 0 (1,0,0)-(1.1,2,1).
  EXPECT_EQ(p[3]["vertices"], nlohmann::json::parse("[[1,0,0],[1,0,1],[1.1,2,1]]"));
  EXPECT_EQ(p[4]["vertices"], nlohmann::json::parse("[[1.1,2,1],[1,2,0],[1,0,0]]"));
  // Kd and Ke as the MTL writes them (0.6 exactly, not the float 0.60000002).
  EXPECT_EQ(p[0]["emission"], nlohmann::json::parse("[10,8,6]"));
  EXPECT_EQ(p[0]["reflectance"], nlohmann::json::parse("[0.5,0.5,0.5]"));
  EXPECT_EQ(p[1]["reflectance"], nlohmann::json::parse("[0.6,0.5,0.4]"));
  EXPECT_EQ(p[2]["reflectance"], nlohmann::json::parse("[0.7,0.7,0.7]"));
  for (std::size_t k = 1; k < p.size(); ++k) EXPECT_FALSE(p[k].contains("emission")) << k;
  EXPECT_EQ(scene["name"], "room");
  EXPECT_EQ(summary.files.size(), 2u);  // the OBJ and its MTL
}

TEST(ModelImport, ElementsFollowTheBudgetOrTheSize) {
  ImportSummary summary;
  ImportOptions options;
  long total = 0;
  const nlohmann::json scene = import_model(model("room.obj"), options, summary);
  for (const nlohmann::json& patch : scene["patches"])
    total += patch["elements"][0].get<long>() * patch["elements"][1].get<long>();
  // 16 per patch by default, spread by area: about 9 x 16 in all (rounding per patch).
  EXPECT_GT(total, 9 * 12);
  EXPECT_LT(total, 9 * 20);
  options.element_size = 0.25;  // the 1 x 2 wall: 4 x 8 cells
  const nlohmann::json sized = import_model(model("room.obj"), options, summary);
  EXPECT_EQ(sized["patches"][2]["elements"], nlohmann::json::parse("[4,8]"));
  options.scale = 2.0;          // twice as large: 8 x 16 cells of 0.25
  const nlohmann::json scaled = import_model(model("room.obj"), options, summary);
  EXPECT_EQ(scaled["patches"][2]["elements"], nlohmann::json::parse("[8,16]"));
  EXPECT_EQ(scaled["patches"][2]["vertices"][2], nlohmann::json::parse("[2,4,0]"));
}

// The OBJ `text` (with a lamp material that emits) imported from a temporary file.
nlohmann::json import_text(const std::string& name, const std::string& text, ImportOptions options,
                           ImportSummary& summary) {
  const fs::path dir = fs::path(testing::TempDir()) / ("model_import_" + name);
  fs::create_directories(dir);
  std::ofstream(dir / "lamp.mtl") << "newmtl lamp\nKd 0.5 0.5 0.5\nKe 1 1 1\n";
  std::ofstream(dir / (name + ".obj")) << "mtllib lamp.mtl\nusemtl lamp\n" << text;
  nlohmann::json scene = import_model((dir / (name + ".obj")).string(), options, summary);
  fs::remove_all(dir);
  return scene;
}

// A budget is shared by area and each share shaped after the patch's edges, worked out by
// hand: budget 12 over a 2 x 1 rectangle (area 2) and a unit square (area 1) is 8 and 4
// elements, 4 along the long edge (v0 -> v1) by 2, and 2 x 2.
TEST(ModelImport, ElementGridFollowsTheEdges) {
  ImportSummary summary;
  ImportOptions options;
  options.element_budget = 12;
  const nlohmann::json scene = import_text(
      "grid", "v 0 0 0\nv 2 0 0\nv 2 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
      "f 1 2 3 4\nf 5 6 7 8\n", options, summary);
  EXPECT_EQ(scene["patches"][0]["elements"], nlohmann::json::parse("[4,2]"));
  EXPECT_EQ(scene["patches"][1]["elements"], nlohmann::json::parse("[2,2]"));
}

// Shares and grids are rounded, not floored (worked out by hand, each case one where floor and
// round differ): budget 7 over a 2 x 1 rectangle and a unit square is 14/3 = 4.67 -> 5 and
// 7/3 = 2.33 -> 2 elements; the rectangle's 5 are sqrt(5 x 2) = 3.16 -> 3 along its long edge
// by 5/3 = 1.67 -> 2 (floored: 4 elements, 3 x 1), the square's 2 are 1 x 2. Budget 5 on a
// 3 x 1 rectangle alone: sqrt(15) = 3.87 -> 4 by 5/4 = 1.25 -> 1 (floored: 3 x 2).
TEST(ModelImport, ElementBudgetIsRoundedNotFloored) {
  ImportSummary summary;
  ImportOptions options;
  options.element_budget = 7;
  const nlohmann::json two = import_text(
      "rounded", "v 0 0 0\nv 2 0 0\nv 2 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
      "f 1 2 3 4\nf 5 6 7 8\n", options, summary);
  EXPECT_EQ(two["patches"][0]["elements"], nlohmann::json::parse("[3,2]"));
  EXPECT_EQ(two["patches"][1]["elements"], nlohmann::json::parse("[1,2]"));
  options.element_budget = 5;
  const nlohmann::json one = import_text(
      "rounded_alone", "v 0 0 0\nv 3 0 0\nv 3 1 0\nv 0 1 0\nf 1 2 3 4\n", options, summary);
  EXPECT_EQ(one["patches"][0]["elements"], nlohmann::json::parse("[4,1]"));
}

// --merge-coplanar merges only pairs that make a planar convex quad: a pair folded along its
// shared edge (the second triangle's far corner 0.5 out of the plane) and a pair that makes a
// concave quad (its corner (1, 0.5) turns the other way) stay two triangles each.
TEST(ModelImport, MergesOnlyPlanarConvexPairs) {
  ImportSummary summary;
  ImportOptions options;
  options.merge_coplanar = true;
  const nlohmann::json folded = import_text(
      "folded", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0.5\nf 1 2 3\nf 1 3 4\n", options, summary);
  EXPECT_EQ(folded["patches"].size(), 2u);
  const nlohmann::json concave = import_text(
      "concave", "v 0 0 0\nv 2 0 0\nv 1 0.5 0\nv 0 2 0\nf 1 2 3\nf 1 3 4\n", options, summary);
  EXPECT_EQ(concave["patches"].size(), 2u);
  const nlohmann::json square = import_text(
      "square", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\n", options, summary);
  EXPECT_EQ(square["patches"].size(), 1u);
  EXPECT_EQ(summary.merged, 1);
}

// --merge-coplanar merges one material's halves only: two triangles of a unit square with the
// same reflectance, one emitting and one not, stay two patches, and only the first emits.
TEST(ModelImport, MergesNoEmitterWithANonEmitterOfTheSameColour) {
  const fs::path dir = fs::path(testing::TempDir()) / "model_import_merge_emitter";
  fs::create_directories(dir);
  std::ofstream(dir / "a.mtl") << "newmtl lamp\nKd 0.5 0.5 0.5\nKe 1 1 1\n"
                                  "newmtl wall\nKd 0.5 0.5 0.5\n";
  std::ofstream(dir / "a.obj") << "mtllib a.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                  "usemtl lamp\nf 1 2 3\nusemtl wall\nf 1 3 4\n";
  ImportSummary summary;
  ImportOptions options;
  options.merge_coplanar = true;
  const nlohmann::json scene = import_model((dir / "a.obj").string(), options, summary);
  fs::remove_all(dir);
  EXPECT_EQ(summary.merged, 0);
  ASSERT_EQ(scene["patches"].size(), 2u);
  EXPECT_EQ(scene["patches"][0]["emission"], nlohmann::json::parse("[1,1,1]"));
  EXPECT_FALSE(scene["patches"][1].contains("emission"));
  EXPECT_EQ(scene["patches"][0]["reflectance"], scene["patches"][1]["reflectance"]);
}

// A colour the file does not give is the documented 0.5 grey, not Assimp's stand-ins: 0.6
// for an MTL material without Kd and for faces without usemtl, white for a glTF material
// without baseColorFactor (which would be refused as a reflectance of 1).
TEST(ModelImport, MissingColoursAreTheDocumentedDefault) {
  const fs::path dir = fs::path(testing::TempDir()) / "model_import_defaults";
  fs::create_directories(dir);
  std::ofstream(dir / "a.mtl") << "newmtl glow\nKe 1 1 1\nnewmtl grey\nKd 0.25 0.25 0.25\n";
  std::ofstream(dir / "a.obj") << "mtllib a.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"
                                  "usemtl glow\nf 1 3 2\nusemtl grey\nf 2 3 1\n";
  std::ofstream(dir / "b.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  std::ofstream(dir / "a.gltf")
      << R"({"asset":{"version":"2.0"},"buffers":[{"uri":"data:application/octet-stream;base64,)"
         R"(AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA","byteLength":36}],)"
         R"("bufferViews":[{"buffer":0,"byteLength":36}],"accessors":[{"bufferView":0,)"
         R"("componentType":5126,"count":3,"type":"VEC3","max":[1,1,0],"min":[0,0,0]}],)"
         R"("materials":[{"name":"glow","emissiveFactor":[1,1,1]}],)"
         R"("meshes":[{"primitives":[{"attributes":{"POSITION":0},"material":0}]}],)"
         R"("nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}],"scene":0})";
  ImportSummary summary;
  ImportOptions options;
  nlohmann::json obj, gltf;
  nlohmann::json plain;
  try {
    obj = import_model((dir / "a.obj").string(), options, summary);
    gltf = import_model((dir / "a.gltf").string(), {}, summary);
    options.lights = {"DefaultMaterial"};
    plain = import_model((dir / "b.obj").string(), options, summary);
  } catch (const InputError& e) {
    FAIL() << e.what();
  }
  fs::remove_all(dir);
  ASSERT_EQ(obj["patches"].size(), 2u);
  const nlohmann::json grey = nlohmann::json::parse("[0.5,0.5,0.5]");
  EXPECT_EQ(obj["patches"][0]["reflectance"], grey);  // no Kd
  EXPECT_EQ(obj["patches"][1]["reflectance"], nlohmann::json::parse("[0.25,0.25,0.25]"));
  EXPECT_EQ(plain["patches"][0]["reflectance"], grey);  // no material at all
  ASSERT_EQ(gltf["patches"].size(), 1u);
  EXPECT_EQ(gltf["patches"][0]["reflectance"], grey);  // no baseColorFactor
}

TEST(ModelImport, FlipsFacesAndMarksLights) {
  ImportSummary summary;
  ImportOptions options;
  options.flip_faces = true;
  options.lights = {"wall=1,2,3"};
  const nlohmann::json scene = import_model(model("room.obj"), options, summary);
  EXPECT_EQ(scene["patches"][1]["vertices"][1], nlohmann::json::parse("[1,0,1]"));  // reversed
  EXPECT_EQ(scene["patches"][2]["emission"], nlohmann::json::parse("[1,2,3]"));
  options.lights = {"wall=1,2"};
  EXPECT_THROW(import_model(model("room.obj"), options, summary), InputError);
}

// The Cornell box as OBJ gives scenes/cornell-box.json's patches exactly: the same corners,
// reflectances and emission, in the same order (the bent right wall cut as the generator cuts it).
TEST(ModelImport, TheCornellBoxObjIsTheCornellBoxScene) {
  ImportSummary summary;
  const nlohmann::json imported = import_model(model("cornell-box.obj"), {}, summary);
  std::ifstream in(std::string(NCUBE_SOURCE_DIR) + "/scenes/cornell-box.json");
  const nlohmann::json reference = nlohmann::json::parse(in);
  ASSERT_EQ(imported["patches"].size(), reference["patches"].size());
  for (std::size_t k = 0; k < reference["patches"].size(); ++k) {
    const nlohmann::json& a = imported["patches"][k];
    const nlohmann::json& b = reference["patches"][k];
    EXPECT_EQ(a["vertices"], b["vertices"]) << k;
    EXPECT_EQ(a["reflectance"], b["reflectance"]) << k;
    EXPECT_EQ(a.value("emission", nlohmann::json()), b.value("emission", nlohmann::json())) << k;
  }
}

// A model through Assimp's glTF exporter: glTF holds triangles only, so each quad comes back as
// two, and --merge-coplanar makes them one patch again: the same scene document, so the same
// run. Through Assimp's PLY exporter the same patches come back (PLY has no materials).
TEST(ModelImport, GltfAndPlyOfAModelAreTheSameScene) {
  Assimp::Importer importer;
  const aiScene* quads = importer.ReadFile(model("quads.obj"), 0);
  ASSERT_NE(quads, nullptr);
  const fs::path dir = fs::path(testing::TempDir()) / "model_import_formats";
  fs::create_directories(dir);
  Assimp::Exporter exporter;
  ASSERT_EQ(exporter.Export(quads, "gltf2", (dir / "quads.gltf").string()), aiReturn_SUCCESS)
      << exporter.GetErrorString();
  ASSERT_EQ(exporter.Export(quads, "ply", (dir / "quads.ply").string()), aiReturn_SUCCESS)
      << exporter.GetErrorString();
  ImportSummary summary;
  ImportOptions options;
  options.merge_coplanar = true;
  nlohmann::json gltf, ply;
  const nlohmann::json obj = import_model(model("quads.obj"), options, summary);
  EXPECT_EQ(summary.merged, 0);
  try {
    gltf = import_model((dir / "quads.gltf").string(), options, summary);
    EXPECT_EQ(summary.merged, 3);  // the three quads' halves
    options.lights = {"quads"};    // a PLY names no material: its file name marks it a light
    ply = import_model((dir / "quads.ply").string(), options, summary);
  } catch (const InputError& e) {
    FAIL() << e.what();
  }
  fs::remove_all(dir);
  EXPECT_EQ(gltf["patches"], obj["patches"]);
  ASSERT_EQ(ply["patches"].size(), obj["patches"].size());
  for (std::size_t k = 0; k < obj["patches"].size(); ++k)
    EXPECT_EQ(ply["patches"][k]["vertices"], obj["patches"][k]["vertices"]) << k;
}

// One small scene written by hand twice: tests/models/two-quads.gltf (two materials, each quad
// as two triangles, glTF having no quads) and tests/models/two-quads.ply (the same quads, each
// with its face colour: 51 102 153 is 0.2 0.4 0.6 exactly as 51/255 rounds to 0.2's double).
// Imported, they are the same scene document, so the same run (model_import_runs_test.sh).
TEST(ModelImport, PlyFaceColoursAndGltfOfOneSceneAreTheSameScene) {
  ImportSummary summary;
  ImportOptions gltf_options, ply_options;
  gltf_options.merge_coplanar = true;
  ply_options.lights = {"two-quads"};  // the glTF's materials emit 1, 1, 1: so does the PLY
  const nlohmann::json gltf = import_model(model("two-quads.gltf"), gltf_options, summary);
  EXPECT_EQ(summary.merged, 2);
  const nlohmann::json ply = import_model(model("two-quads.ply"), ply_options, summary);
  ASSERT_EQ(ply["patches"].size(), 2u);
  EXPECT_EQ(ply["patches"][0]["reflectance"], nlohmann::json::parse("[0.2,0.4,0.6]"));
  EXPECT_EQ(ply["patches"][1]["reflectance"], nlohmann::json::parse("[0.8,0.4,0]"));
  EXPECT_EQ(ply["patches"][1]["vertices"], nlohmann::json::parse("[[0,1,0],[1,1,0],[1,1,1],[0,1,1]]"));
  EXPECT_EQ(gltf, ply);
}

// Face colours in a binary big-endian PLY, as floats, between properties that are read past
// (a vertex's confidence, a face's flags after its colour).
TEST(ModelImport, BinaryPlyFaceColours) {
  const fs::path dir = fs::path(testing::TempDir()) / "model_import_binary_ply";
  fs::create_directories(dir);
  std::string body;
  const auto put = [&body](const void* value, int bytes) {  // big-endian, whatever the host
    unsigned char raw[4];
    std::memcpy(raw, value, std::size_t(bytes));
    const std::uint16_t probe = 1;
    if (*reinterpret_cast<const unsigned char*>(&probe) == 1) std::reverse(raw, raw + bytes);
    body.append(reinterpret_cast<const char*>(raw), std::size_t(bytes));
  };
  const float corners[4][3] = {{0, 0, 0}, {2, 0, 0}, {2, 0, -1}, {0, 0, -1}};
  for (const auto& c : corners) {
    for (float x : c) put(&x, 4);
    const float confidence = 7;
    put(&confidence, 4);
  }
  body += char(4);
  for (std::int32_t k : {0, 1, 2, 3}) put(&k, 4);
  for (float channel : {0.25f, 0.5f, 0.75f}) put(&channel, 4);
  body += char(9);  // flags
  const std::string header =
      "ply\nformat binary_big_endian 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
      "property float z\nproperty float confidence\nelement face 1\n"
      "property list uchar int vertex_indices\nproperty float red\nproperty float green\n"
      "property float blue\nproperty uchar flags\nend_header\n";
  std::ofstream(dir / "floor.ply", std::ios::binary) << header << body;
  ImportSummary summary;
  ImportOptions options;
  options.lights = {"floor"};
  const nlohmann::json scene = import_model((dir / "floor.ply").string(), options, summary);
  fs::remove_all(dir);
  ASSERT_EQ(scene["patches"].size(), 1u);
  EXPECT_EQ(scene["patches"][0]["reflectance"], nlohmann::json::parse("[0.25,0.5,0.75]"));
  EXPECT_EQ(scene["patches"][0]["vertices"], nlohmann::json::parse("[[0,0,0],[2,0,0],[2,0,-1],[0,0,-1]]"));
}

// tests/models/lamp.gltf, written by hand: a camera node at (0.5, 1, 3) with yfov 0.75 rad
// looking down its -z, a light of emissive (1, 0.8, 0.6) x KHR_materials_emissive_strength 10,
// and a floor quad as two triangles.
TEST(ModelImport, ReadsTheGltfCameraAndEmissiveStrength) {
  ImportSummary summary;
  ImportOptions options;
  options.merge_coplanar = true;
  const nlohmann::json scene = import_model(model("lamp.gltf"), options, summary);
  EXPECT_EQ(scene["camera"]["eye"], nlohmann::json::parse("[0.5,1,3]"));
  EXPECT_EQ(scene["camera"]["look_at"], nlohmann::json::parse("[0.5,1,2]"));
  EXPECT_EQ(scene["camera"]["up"], nlohmann::json::parse("[0,1,0]"));
  EXPECT_NEAR(scene["camera"]["fov_deg"].get<double>(), 0.75 * 180 / M_PI, 1e-4);
  ASSERT_EQ(scene["patches"].size(), 2u);
  EXPECT_EQ(scene["patches"][0]["emission"], nlohmann::json::parse("[10,8,6]"));
  EXPECT_EQ(scene["patches"][1]["reflectance"], nlohmann::json::parse("[0.25,0.5,0.75]"));
  EXPECT_EQ(scene["patches"][1]["vertices"].size(), 4u);  // the floor's two triangles, merged
  EXPECT_EQ(summary.merged, 1);
}

// --scale moves the whole camera with the model: lamp.gltf at twice its size has its eye at
// (1, 2, 6) and looks at (1, 2, 4), one unit of the model (two now) down -z; up stays a direction.
TEST(ModelImport, ScaleMovesTheGltfCameraEyeAndTarget) {
  ImportSummary summary;
  ImportOptions options;
  options.scale = 2.0;
  const nlohmann::json scene = import_model(model("lamp.gltf"), options, summary);
  EXPECT_EQ(scene["camera"]["eye"], nlohmann::json::parse("[1,2,6]"));
  EXPECT_EQ(scene["camera"]["look_at"], nlohmann::json::parse("[1,2,4]"));
  EXPECT_EQ(scene["camera"]["up"], nlohmann::json::parse("[0,1,0]"));
}

// The same lamp as a .glb (the binary container: a JSON chunk, then the buffer as a BIN chunk),
// written here from lamp.gltf: the camera, the strength (read from the JSON chunk) and the
// patches are the .gltf's.
TEST(ModelImport, GlbIsTheGltfScene) {
  nlohmann::json document = nlohmann::json::parse(std::ifstream(model("lamp.gltf")));
  const std::string uri = document["buffers"][0]["uri"];
  const std::string base64 = uri.substr(uri.find(',') + 1);
  std::string bytes;  // base64 decoded: 4 characters are 3 bytes
  const std::string alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  unsigned bits = 0;
  int count = 0;
  for (char c : base64) {
    if (c == '=') break;
    bits = (bits << 6) | unsigned(alphabet.find(c));
    if ((count += 6) >= 8) bytes += char((bits >> (count -= 8)) & 0xff);
  }
  ASSERT_EQ(bytes.size(), document["buffers"][0]["byteLength"].get<std::size_t>());
  document["buffers"][0].erase("uri");
  std::string json = document.dump();
  json.resize((json.size() + 3) / 4 * 4, ' ');
  bytes.resize((bytes.size() + 3) / 4 * 4, '\0');
  std::string glb;
  const auto word = [&glb](std::uint32_t v) {  // little-endian, whatever the host
    for (int k = 0; k < 4; ++k) glb += char((v >> (8 * k)) & 0xff);
  };
  word(0x46546C67);  // "glTF"
  word(2);
  word(std::uint32_t(12 + 8 + json.size() + 8 + bytes.size()));
  word(std::uint32_t(json.size()));
  word(0x4E4F534A);  // "JSON"
  glb += json;
  word(std::uint32_t(bytes.size()));
  word(0x004E4942);  // "BIN"
  glb += bytes;
  const fs::path dir = fs::path(testing::TempDir()) / "model_import_glb";
  fs::create_directories(dir);
  std::ofstream(dir / "lamp.glb", std::ios::binary) << glb;
  ImportSummary summary;
  ImportOptions options;
  options.merge_coplanar = true;
  nlohmann::json from_glb;
  try {
    from_glb = import_model((dir / "lamp.glb").string(), options, summary);
  } catch (const InputError& e) {
    FAIL() << e.what();
  }
  fs::remove_all(dir);
  EXPECT_EQ(from_glb["patches"][0]["emission"], nlohmann::json::parse("[10,8,6]"));
  EXPECT_EQ(from_glb, import_model(model("lamp.gltf"), options, summary));
}

// A node scaled by -1 in x mirrors two-quads.gltf: the corners' x change sign and their order
// is turned around, so the floor still faces up (+y) and the ceiling down (glTF's rule: a
// negative determinant means the winding is reversed).
TEST(ModelImport, MirroredNodeKeepsTheFrontSide) {
  nlohmann::json document = nlohmann::json::parse(std::ifstream(model("two-quads.gltf")));
  document["nodes"][0]["scale"] = {-1, 1, 1};
  const fs::path dir = fs::path(testing::TempDir()) / "model_import_mirror";
  fs::create_directories(dir);
  std::ofstream(dir / "two-quads.gltf") << document.dump();
  ImportSummary summary;
  ImportOptions options;
  options.merge_coplanar = true;
  const nlohmann::json scene = import_model((dir / "two-quads.gltf").string(), options, summary);
  fs::remove_all(dir);
  const auto normal_y = [&scene](std::size_t k) {  // Newell's y component: 2 x area x n.y
    const nlohmann::json& v = scene["patches"][k]["vertices"];
    double y = 0;
    for (std::size_t i = 0; i < v.size(); ++i) {
      const nlohmann::json& a = v[i];
      const nlohmann::json& b = v[(i + 1) % v.size()];
      y += (a[2].get<double>() - b[2].get<double>()) * (a[0].get<double>() + b[0].get<double>());
    }
    return y;
  };
  ASSERT_EQ(scene["patches"].size(), 2u);
  // The halves (2, 1, 0) and (3, 2, 0) of the mirrored floor, merged from corner 2.
  EXPECT_EQ(scene["patches"][0]["vertices"], nlohmann::json::parse("[[-1,0,1],[0,0,1],[0,0,0],[-1,0,0]]"));
  EXPECT_GT(normal_y(0), 0.0);  // the floor faces up
  EXPECT_LT(normal_y(1), 0.0);  // the ceiling faces down
}

// --flip-faces turns a mirrored node's faces around too: two-quads.gltf mirrored in x (whose
// floor faces up without the option, above) has its floor facing down and its ceiling up.
TEST(ModelImport, FlipFacesTurnsAMirroredNodeAround) {
  nlohmann::json document = nlohmann::json::parse(std::ifstream(model("two-quads.gltf")));
  document["nodes"][0]["scale"] = {-1, 1, 1};
  const fs::path dir = fs::path(testing::TempDir()) / "model_import_mirror_flip";
  fs::create_directories(dir);
  std::ofstream(dir / "two-quads.gltf") << document.dump();
  ImportSummary summary;
  ImportOptions options;
  options.flip_faces = true;
  const nlohmann::json scene = import_model((dir / "two-quads.gltf").string(), options, summary);
  fs::remove_all(dir);
  // Newell's y component of each patch: twice its area (1/2: without --merge-coplanar each
  // triangle is a patch) times n.y. The floor's two triangles come first, then the ceiling's.
  const auto normal_y = [&scene](std::size_t k) {
    const nlohmann::json& v = scene["patches"][k]["vertices"];
    double y = 0;
    for (std::size_t i = 0; i < v.size(); ++i) {
      const nlohmann::json& a = v[i];
      const nlohmann::json& b = v[(i + 1) % v.size()];
      y += (a[2].get<double>() - b[2].get<double>()) * (a[0].get<double>() + b[0].get<double>());
    }
    return y;
  };
  ASSERT_EQ(scene["patches"].size(), 4u);
  for (std::size_t k : {0u, 1u}) {
    EXPECT_NEAR(normal_y(k), -1.0, 1e-12) << "floor triangle " << k << " must face down";
    EXPECT_LE(scene["patches"][k]["vertices"][0][0].get<double>(), 0.0);  // mirrored: x <= 0
  }
  for (std::size_t k : {2u, 3u}) EXPECT_NEAR(normal_y(k), 1.0, 1e-12) << "ceiling triangle " << k;
}

struct BadModel : testing::Test {
  fs::path dir;
  void SetUp() override {
    dir = fs::path(testing::TempDir()) /
          ("bad_model_" + std::string(testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::create_directories(dir);
  }
  void TearDown() override { fs::remove_all(dir); }
  // The message of importing a file with `text`, or "" if it was accepted.
  std::string refusal(const std::string& name, const std::string& text, ImportOptions options = {}) {
    const fs::path path = dir / name;
    std::ofstream(path, std::ios::binary) << text;
    ImportSummary summary;
    try {
      import_model(path.string(), options, summary);
    } catch (const InputError& e) {
      const std::string message = e.what();
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
      return message;
    }
    return "";
  }
};

const char* kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

TEST_F(BadModel, OutOfRangeIndex) {
  EXPECT_NE(refusal("a.obj", std::string(kTriangle) + "f 1 2 9\n").find("out of range"), std::string::npos);
}

TEST_F(BadModel, NanCoordinate) {
  EXPECT_NE(refusal("a.obj", "v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").find("not a finite point"),
            std::string::npos);
}

TEST_F(BadModel, MissingMaterialLibrary) {
  EXPECT_NE(refusal("a.obj", std::string("mtllib gone.mtl\n") + kTriangle + "usemtl x\nf 1 2 3\n")
                .find("gone.mtl: cannot open model part: No such file or directory"),
            std::string::npos);
}

TEST_F(BadModel, FacesWithOneOrTwoCorners) {
  EXPECT_NE(refusal("a.obj", std::string(kTriangle) + "f 1 2\n").find("2 corners"), std::string::npos);
  EXPECT_NE(refusal("b.obj", std::string(kTriangle) + "f 1\n").find("1 corner"), std::string::npos);
}

TEST_F(BadModel, ReflectanceOfOneOrMore) {
  std::ofstream(dir / "a.mtl") << "newmtl white\nKd 1 1 1\nKe 1 1 1\n";
  EXPECT_NE(refusal("a.obj", std::string("mtllib a.mtl\n") + kTriangle + "usemtl white\nf 1 2 3\n")
                .find("material \"white\": reflectance"),
            std::string::npos);
}

// A --light that names no material or mesh (a typing error) is refused, not ignored, and the
// message lists the names there are.
TEST_F(BadModel, LightNamingNothing) {
  std::ofstream(dir / "a.mtl") << "newmtl lamp\nKe 1 1 1\n";
  ImportOptions options;
  options.lights = {"lamb=2,2,2"};
  EXPECT_NE(refusal("a.obj", std::string("mtllib a.mtl\n") + kTriangle + "usemtl lamp\nf 1 2 3\n", options)
                .find("--light lamb=2,2,2: " + (dir / "a.obj").string() + " has no material or mesh of that name"),
            std::string::npos);
}

// Assimp gives a face after mtllib and before any usemtl the library's last material (here
// "lamp", a light): refused instead, naming the line.
TEST_F(BadModel, FaceBeforeUsemtl) {
  std::ofstream(dir / "a.mtl") << "newmtl wall\nKd 0.5 0.5 0.5\nnewmtl lamp\nKe 1 1 1\n";
  EXPECT_NE(refusal("a.obj", std::string("mtllib a.mtl\n") + kTriangle + "f 1 2 3\nusemtl wall\nf 1 3 2\n")
                .find("line 5: a face after mtllib and before any usemtl"),
            std::string::npos);
}

// A usemtl naming no material of the library (a typing error) would be a default grey.
TEST_F(BadModel, UsemtlNamingNothing) {
  std::ofstream(dir / "a.mtl") << "newmtl grey\nKd 0.5 0.5 0.5\nnewmtl lamp\nKe 1 1 1\n";
  EXPECT_NE(refusal("a.obj", std::string("mtllib a.mtl\n") + kTriangle + "usemtl lamp\nf 1 2 3\nusemtl gery\nf 1 3 2\n")
                .find("line 7: usemtl gery: no material library of the model defines it"),
            std::string::npos);
  EXPECT_NE(refusal("b.obj", std::string(kTriangle) + "usemtl lamp\nf 1 2 3\n")
                .find("line 4: usemtl lamp: no material library"),
            std::string::npos);
}

TEST_F(BadModel, NoLight) {
  EXPECT_NE(refusal("a.obj", std::string(kTriangle) + "f 1 2 3\n").find("--light"), std::string::npos);
}

TEST_F(BadModel, GltfWithABrokenBuffer) {
  const std::string gltf =
      R"({"asset":{"version":"2.0"},"buffers":[{"uri":"gone.bin","byteLength":36}],)"
      R"("bufferViews":[{"buffer":0,"byteLength":36}],"accessors":[{"bufferView":0,)"
      R"("componentType":5126,"count":3,"type":"VEC3","max":[1,1,0],"min":[0,0,0]}],)"
      R"("meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],"nodes":[{"mesh":0}],)"
      R"("scenes":[{"nodes":[0]}],"scene":0})";
  EXPECT_NE(refusal("a.gltf", gltf).find("gone.bin"), std::string::npos);
  std::ofstream(dir / "short.bin", std::ios::binary) << std::string(12, '\0');  // 12 of 36 bytes
  std::string short_buffer = gltf;
  short_buffer.replace(short_buffer.find("gone.bin"), 8, "short.bin");
  EXPECT_NE(refusal("b.gltf", short_buffer), "");
}

TEST_F(BadModel, PlyThatLiesAboutItsLength) {
  const std::string header = "ply\nformat ascii 1.0\nelement vertex 100\nproperty float x\n"
                             "property float y\nproperty float z\nelement face 1\n"
                             "property list uchar int vertex_indices\nend_header\n";
  EXPECT_NE(refusal("a.ply", header + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n").find("declares 100 vertex"),
            std::string::npos);
  const std::string binary = "ply\nformat binary_little_endian 1.0\nelement vertex 3\n"
                             "property float x\nproperty float y\nproperty float z\n"
                             "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  EXPECT_NE(refusal("b.ply", binary + std::string(20, '\0')).find("bytes of data"), std::string::npos);
}

// A face colour of 255 is 1, a reflectance that never loses energy; two of three channels is
// no colour. Both refused, not clamped or ignored.
TEST_F(BadModel, PlyFaceColours) {
  const std::string header = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                             "property float y\nproperty float z\nelement face 1\n"
                             "property list uchar int vertex_indices\n";
  const std::string corners = "0 0 0\n1 0 0\n0 1 0\n";
  ImportOptions light;
  light.lights = {"a", "b"};
  EXPECT_NE(refusal("a.ply", header + "property uchar red\nproperty uchar green\nproperty uchar blue\n"
                             "end_header\n" + corners + "3 0 1 2 255 0 0\n", light)
                .find("face 0: face colour 1 0 0: each channel must be in [0, 1)"),
            std::string::npos);
  EXPECT_NE(refusal("b.ply", header + "property uchar red\nproperty uchar green\nend_header\n" +
                                 corners + "3 0 1 2 9 9\n", light)
                .find("2 of the three colour properties"),
            std::string::npos);
}

// A PLY cut inside its header: Assimp 5.2 reads it forever (found by mutating
// tests/models/two-quads.ply at random); refused before Assimp sees it.
TEST_F(BadModel, PlyCutInItsHeader) {
  EXPECT_NE(refusal("a.ply", "ply\nformat ascii 1.0\ncomment cut here").find("no end_header"),
            std::string::npos);
  EXPECT_NE(refusal("b.ply", "ply\nformat text 1.0\nend_header\n").find("PLY format \"text\""),
            std::string::npos);
}

TEST_F(BadModel, TooLargeIsRefusedBeforeReading) {
  const fs::path path = dir / "huge.obj";
  std::ofstream(path) << "v 0 0 0\n";
  fs::resize_file(path, (std::uintmax_t(256) << 20) + 1);  // sparse: no disk used
  ImportSummary summary;
  try {
    import_model(path.string(), {}, summary);
    FAIL() << "a model over 256 MiB was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("larger than"), std::string::npos) << e.what();
  }
}

// A glTF whose buffer is over the limit is refused before Assimp reads the buffer.
TEST_F(BadModel, TooLargeBufferIsRefusedBeforeReading) {
  std::ofstream(dir / "huge.bin") << "x";
  fs::resize_file(dir / "huge.bin", (std::uintmax_t(256) << 20) + 1);  // sparse
  const std::string gltf =
      R"({"asset":{"version":"2.0"},"buffers":[{"uri":"huge.bin","byteLength":36}],)"
      R"("bufferViews":[{"buffer":0,"byteLength":36}],"accessors":[{"bufferView":0,)"
      R"("componentType":5126,"count":3,"type":"VEC3","max":[1,1,0],"min":[0,0,0]}],)"
      R"("meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],"nodes":[{"mesh":0}],)"
      R"("scenes":[{"nodes":[0]}],"scene":0})";
  EXPECT_NE(refusal("a.gltf", gltf).find("huge.bin: model part is larger than 268435456 bytes (the limit)"), std::string::npos);
}

}  // namespace
}  // namespace ncube

#include "scene/scene_loader.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "util/input_error.h"

namespace ncube {
namespace {

using json = nlohmann::json;

// A small valid scene: a square light in the plane y = 2 facing down (patch 0) and a
// triangle on the floor facing up (patch 1). Tests break one field at a time.
json valid_scene() {
  return json::parse(R"({
    "name": "room",
    "camera": {"eye": [0, 1, 5], "look_at": [0, 1, 0], "up": [0, 1, 0], "fov_deg": 40},
    "patches": [
      {"vertices": [[0, 2, 0], [1, 2, 0], [1, 2, 1], [0, 2, 1]],
       "reflectance": [0.5, 0.5, 0.5], "emission": [10, 8, 6], "elements": [2, 3]},
      {"vertices": [[0, 0, 0], [0, 0, 1], [1, 0, 0]],
       "reflectance": [0.2, 0.4, 0.6], "elements": [2, 2]}
    ]})");
}

// The message of the InputError that parsing `text` (or `scene`) throws; "" and a test
// failure if none.
std::string error_of_text(const std::string& text) {
  try {
    parse_scene(text, "test.json");
  } catch (const InputError& error) {
    return error.what();
  }
  ADD_FAILURE() << "no InputError for: " << text;
  return "";
}
std::string error_of(const json& scene) { return error_of_text(scene.dump()); }

// The scene with patch `index`'s field `key` set to `value`.
json with_patch_field(int index, const std::string& key, const json& value) {
  json scene = valid_scene();
  scene["patches"][index][key] = value;
  return scene;
}

json with_vertices(const json& vertices) { return with_patch_field(1, "vertices", vertices); }

json with_camera_field(const std::string& key, const json& value) {
  json scene = valid_scene();
  scene["camera"][key] = value;
  return scene;
}

// ------------------------------------------------------------------ correct parsing

TEST(SceneLoader, ParsesEveryField) {
  const Scene scene = parse_scene(valid_scene().dump(), "test.json");
  EXPECT_EQ(scene.name, "room");
  EXPECT_EQ(scene.camera.eye, Vec3(0, 1, 5));
  EXPECT_EQ(scene.camera.look_at, Vec3(0, 1, 0));
  EXPECT_EQ(scene.camera.up, Vec3(0, 1, 0));
  EXPECT_EQ(scene.camera.fov_deg, 40.0);
  ASSERT_EQ(scene.patches.size(), 2u);
  const Patch& light = scene.patches[0];
  EXPECT_EQ(light.polygon.count, 4);
  EXPECT_EQ(light.polygon[2], Vec3(1, 2, 1));
  EXPECT_EQ(light.reflectance, Rgb(0.5));
  EXPECT_EQ(light.emission, Rgb(10, 8, 6));
  EXPECT_EQ(light.nu, 2);
  EXPECT_EQ(light.nv, 3);
  // Counter-clockwise seen from below: the light faces down.
  EXPECT_EQ(light.normal, Vec3(0, -1, 0));
  EXPECT_DOUBLE_EQ(light.area, 1.0);
  // build_elements ran: 2 x 3 + 2 x 2 elements, the triangle's after the light's.
  EXPECT_EQ(scene.elements.size(), 10u);
  EXPECT_EQ(scene.patches[1].first_element, 6);
}

TEST(SceneLoader, AppliesDefaults) {
  json text = valid_scene();
  text.erase("camera");
  text["patches"][1].erase("elements");
  const Scene scene = parse_scene(text.dump(), "test.json");
  const Patch& floor = scene.patches[1];
  EXPECT_EQ(floor.emission, Rgb(0.0));
  EXPECT_EQ(floor.nu, 1);
  EXPECT_EQ(floor.nv, 1);
  const Camera expected = default_camera(scene);
  EXPECT_EQ(scene.camera.eye, expected.eye);
  EXPECT_EQ(scene.camera.look_at, expected.look_at);
  EXPECT_EQ(scene.camera.up, expected.up);
  EXPECT_EQ(scene.camera.fov_deg, expected.fov_deg);
}

TEST(SceneLoader, ParsesTriangle) {
  const Scene scene = parse_scene(valid_scene().dump(), "test.json");
  const Patch& floor = scene.patches[1];
  EXPECT_EQ(floor.polygon.count, 3);
  EXPECT_EQ(floor.polygon[1], Vec3(0, 0, 1));
  EXPECT_EQ(floor.normal, Vec3(0, 1, 0));
  EXPECT_DOUBLE_EQ(floor.area, 0.5);
  EXPECT_EQ(floor.element_count(), 4);
  // A triangle's nu x nv cells cover it exactly; the last row's cells are triangles.
  double area = 0.0;
  for (int e = floor.first_element; e < floor.first_element + 4; ++e) {
    area += scene.elements[e].area;
    EXPECT_EQ(scene.elements[e].patch, 1);
  }
  EXPECT_DOUBLE_EQ(area, 0.5);
  EXPECT_EQ(scene.elements[floor.first_element + 3].polygon.count, 3);
}

TEST(SceneLoader, ClockwiseQuadIsValidAndFacesTheOtherWay) {
  const json scene = with_patch_field(0, "vertices", {{0, 2, 0}, {0, 2, 1}, {1, 2, 1}, {1, 2, 0}});
  EXPECT_EQ(parse_scene(scene.dump(), "test.json").patches[0].normal, Vec3(0, 1, 0));
}

TEST(SceneLoader, LoadsFile) {
  const std::string path =
      testing::TempDir() + "scene_loader_test_" + std::to_string(getpid()) + ".json";
  std::ofstream(path) << valid_scene().dump(2);
  const Scene scene = load_scene(path);
  std::remove(path.c_str());
  EXPECT_EQ(scene.name, "room");
  EXPECT_EQ(scene.patches.size(), 2u);
}

// ------------------------------------------------------------- files and JSON syntax

TEST(SceneLoaderError, MissingFile) {
  try {
    load_scene("/nonexistent/scene.json");
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()),
              "/nonexistent/scene.json: cannot open scene file: No such file or directory");
  }
}

TEST(SceneLoaderError, UnreadableFile) {
  try {
    load_scene(testing::TempDir());  // a folder is refused as soon as it is opened
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find(": scene file is a folder, not a regular file"),
              std::string::npos)
        << error.what();
  }
}

TEST(SceneLoaderError, MalformedJsonGivesLineAndColumn) {
  EXPECT_EQ(error_of_text("{\n  \"name\": \"x\",\n  \"patches\": [}\n"),
            "test.json:3:15: malformed JSON: syntax error while parsing value - unexpected '}'; "
            "expected '[', '{', or a literal");
  EXPECT_EQ(error_of_text("{\"name\": \"x\",}").rfind("test.json:1:14: malformed JSON: ", 0), 0u);
  EXPECT_EQ(error_of_text("").rfind("test.json:1:1: malformed JSON: ", 0), 0u);
}

TEST(SceneLoaderError, NonFiniteNumbers) {
  // JSON has no NaN literal; an overflowing number is reported at its last character.
  EXPECT_EQ(error_of_text("{\"name\": \"x\",\n \"patches\": [1e999]}"),
            "test.json:2:18: malformed JSON: number overflow parsing '1e999'");
  EXPECT_EQ(error_of_text("{\"name\": \"x\", \"patches\": [-1e400]}").rfind("test.json:1:", 0), 0u);
  EXPECT_EQ(error_of_text("{\"name\": NaN}").rfind("test.json:1:10: malformed JSON: ", 0), 0u);
  EXPECT_EQ(error_of_text("{\"name\": Infinity}").rfind("test.json:1:10: malformed JSON: ", 0), 0u);
}

TEST(SceneLoaderError, DuplicateKey) {
  const std::string suffix = " (each key may appear once per object)";
  EXPECT_EQ(error_of_text(R"({"name": "a", "name": "b", "patches": []})"),
            "test.json: duplicate key \"name\"" + suffix);
  EXPECT_EQ(error_of_text(R"({"camera": {"up": [0, 1, 0], "up": [0, 1, 0]}})"),
            "test.json: field \"camera\": duplicate key \"up\"" + suffix);
  // The patch index counts every entry of "patches", whatever its type.
  EXPECT_EQ(error_of_text(R"({"name": "a", "patches": [{"elements": [1, 1]}, 3, [{"x": 1}],
                          {"vertices": [], "emission": [1, 1, 1], "emission": [0, 0, 0]}]})"),
            "test.json: patch 3: duplicate key \"emission\"" + suffix);
}

// ------------------------------------------------------------------------ top level

TEST(SceneLoaderError, TopLevel) {
  EXPECT_EQ(error_of_text("[1, 2]"), "test.json: the scene must be a JSON object, got array");
  json scene = valid_scene();
  scene["patchs"] = json::array();
  EXPECT_EQ(error_of(scene), "test.json: unknown key \"patchs\" (allowed: name, camera, patches)");

  scene = valid_scene();
  scene.erase("name");
  EXPECT_EQ(error_of(scene), "test.json: field \"name\": is missing (required)");
  scene["name"] = 3;
  EXPECT_EQ(error_of(scene), "test.json: field \"name\": must be a string, got integer");
  scene["name"] = "";
  EXPECT_EQ(error_of(scene), "test.json: field \"name\": must not be empty");
}

TEST(SceneLoaderError, Patches) {
  json scene = valid_scene();
  scene.erase("patches");
  EXPECT_EQ(error_of(scene), "test.json: field \"patches\": is missing (required)");
  scene["patches"] = json::object();
  EXPECT_EQ(error_of(scene), "test.json: field \"patches\": must be an array, got object");
  scene["patches"] = json::array();
  EXPECT_EQ(error_of(scene),
            "test.json: field \"patches\": is empty; a scene needs at least one patch");
  scene["patches"] = {valid_scene()["patches"][0], "wall"};
  EXPECT_EQ(error_of(scene), "test.json: patch 1: must be an object, got string");
}

TEST(SceneLoaderError, NoEmitter) {
  const json scene = with_patch_field(0, "emission", {0, 0, 0});
  EXPECT_EQ(error_of(scene),
            "test.json: field \"patches\": no patch has a non-zero \"emission\"; a scene needs "
            "a light");
}

// --------------------------------------------------------------------------- camera

TEST(SceneLoaderError, CameraKeysAndTypes) {
  json scene = valid_scene();
  scene["camera"] = "front";
  EXPECT_EQ(error_of(scene), "test.json: field \"camera\": must be an object, got string");
  EXPECT_EQ(error_of(with_camera_field("fov", 40)),
            "test.json: field \"camera\": unknown key \"fov\" (allowed: eye, look_at, up, "
            "fov_deg)");
  scene = valid_scene();
  scene["camera"].erase("up");
  EXPECT_EQ(error_of(scene), "test.json: field \"camera.up\": is missing (required)");
  EXPECT_EQ(error_of(with_camera_field("eye", {0, 1})),
            "test.json: field \"camera.eye\": must be an array of 3 numbers, got an array of 2");
  EXPECT_EQ(error_of(with_camera_field("look_at", {0, "1", 0})),
            "test.json: field \"camera.look_at\": coordinate 1 must be a number, got string");
  EXPECT_EQ(error_of(with_camera_field("fov_deg", "wide")),
            "test.json: field \"camera.fov_deg\": must be a number, got string");
}

TEST(SceneLoaderError, CameraValues) {
  for (const json& fov : {json(0), json(180), json(-5.5), json(200)})
    EXPECT_EQ(error_of(with_camera_field("fov_deg", fov)),
              "test.json: field \"camera.fov_deg\": is " + fov.dump() + ", must be in (0, 180)");
  EXPECT_EQ(error_of(with_camera_field("look_at", {0, 1, 5})),
            "test.json: field \"camera.look_at\": equals camera.eye, so there is no view "
            "direction");
  EXPECT_EQ(error_of(with_camera_field("up", {0, 0, -3})),
            "test.json: field \"camera.up\": is parallel to the view direction (look_at - eye)");
  EXPECT_EQ(error_of(with_camera_field("up", {0, 0, 0})),
            "test.json: field \"camera.up\": must not be the zero vector");
}

// ---------------------------------------------------------------------- patch fields

TEST(SceneLoaderError, UnknownPatchKey) {
  json scene = valid_scene();
  scene["patches"][1]["reflectence"] = {0.5, 0.5, 0.5};
  EXPECT_EQ(error_of(scene),
            "test.json: patch 1: unknown key \"reflectence\" (allowed: vertices, reflectance, "
            "emission, elements)");
}

TEST(SceneLoaderError, Reflectance) {
  json scene = valid_scene();
  scene["patches"][1].erase("reflectance");
  EXPECT_EQ(error_of(scene), "test.json: patch 1: field \"reflectance\": is missing (required)");
  EXPECT_EQ(error_of(with_patch_field(1, "reflectance", "grey")),
            "test.json: patch 1: field \"reflectance\": must be an array of 3 numbers, got "
            "string");
  EXPECT_EQ(error_of(with_patch_field(1, "reflectance", {0.5, 0.5})),
            "test.json: patch 1: field \"reflectance\": must be an array of 3 numbers, got an "
            "array of 2");
  EXPECT_EQ(error_of(with_patch_field(1, "reflectance", {0.5, 1.2, 0.5})),
            "test.json: patch 1: field \"reflectance\": channel 1 is 1.2, must be in [0, 1)");
  EXPECT_EQ(error_of(with_patch_field(1, "reflectance", {0.5, 0.5, 1})),
            "test.json: patch 1: field \"reflectance\": channel 2 is 1, must be in [0, 1)");
  EXPECT_EQ(error_of(with_patch_field(1, "reflectance", {-0.1, 0.5, 0.5})),
            "test.json: patch 1: field \"reflectance\": channel 0 is -0.1, must be in [0, 1)");
  EXPECT_EQ(error_of(with_patch_field(1, "reflectance", {0.5, nullptr, 0.5})),
            "test.json: patch 1: field \"reflectance\": channel 1 must be a number, got null");
}

TEST(SceneLoaderError, Emission) {
  EXPECT_EQ(error_of(with_patch_field(1, "emission", {0, -2, 0})),
            "test.json: patch 1: field \"emission\": channel 1 is -2, must be >= 0");
  EXPECT_EQ(error_of(with_patch_field(1, "emission", true)),
            "test.json: patch 1: field \"emission\": must be an array of 3 numbers, got boolean");
}

TEST(SceneLoaderError, Elements) {
  const std::string prefix = "test.json: patch 0: field \"elements\": ";
  EXPECT_EQ(error_of(with_patch_field(0, "elements", {2.5, 1})),
            prefix + "nu must be an integer, got 2.5");
  EXPECT_EQ(error_of(with_patch_field(0, "elements", {1, 2.0})),
            prefix + "nv must be an integer, got 2.0");
  EXPECT_EQ(error_of(with_patch_field(0, "elements", {1, 1e30})),
            prefix + "nv must be an integer, got 1e+30");
  EXPECT_EQ(error_of(with_patch_field(0, "elements", {0, 1})), prefix + "nu is 0, must be >= 1");
  EXPECT_EQ(error_of(with_patch_field(0, "elements", {1, -3})), prefix + "nv is -3, must be >= 1");
  EXPECT_EQ(error_of(with_patch_field(0, "elements", {"2", 1})),
            prefix + "nu must be an integer, got \"2\"");
  EXPECT_EQ(error_of(with_patch_field(0, "elements", {4})),
            prefix + "must be an array [nu, nv] of 2 integers, got [4]");
  EXPECT_EQ(error_of(with_patch_field(0, "elements", 4)),
            prefix + "must be an array [nu, nv] of 2 integers, got 4");
}

TEST(SceneLoaderError, AbsurdlyManyElements) {
  const std::string prefix = "test.json: patch 0: field \"elements\": ";
  EXPECT_EQ(error_of(with_patch_field(0, "elements", {1, 18446744073709551615ull})),
            prefix +
                "nv is 18446744073709551615, absurdly large (limit 1048576 elements per "
                "patch)");
  EXPECT_EQ(error_of(with_patch_field(0, "elements", {2000, 2000})),
            prefix + "2000 x 2000 = 4000000 elements, absurdly large (limit 1048576 per patch)");
  // Each patch within the per-patch limit, but 17 of them exceed the scene limit.
  json scene = valid_scene();
  scene["patches"][0]["elements"] = {1024, 1024};
  for (int i = 1; i <= 16; ++i) scene["patches"][i] = scene["patches"][0];
  EXPECT_EQ(error_of(scene),
            "test.json: patch 16: field \"elements\": brings the scene to 17825792 elements, "
            "absurdly large (limit 16777216 per scene)");
}

TEST(SceneLoaderError, VertexTypes) {
  const std::string prefix = "test.json: patch 1: field \"vertices\": ";
  json scene = valid_scene();
  scene["patches"][1].erase("vertices");
  EXPECT_EQ(error_of(scene), prefix + "is missing (required)");
  EXPECT_EQ(error_of(with_vertices("square")),
            prefix + "must be an array of 3 or 4 vertices, got string");
  EXPECT_EQ(error_of(with_vertices({{0, 0, 0}, {1, 0, 0}})),
            prefix + "must be an array of 3 or 4 vertices, got an array of 2");
  EXPECT_EQ(error_of(with_vertices({{0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}, {0.5, 0, 0}})),
            prefix + "must be an array of 3 or 4 vertices, got an array of 5");
  EXPECT_EQ(error_of(with_vertices({{0, 0, 0}, {0, 0}, {1, 0, 0}})),
            prefix + "vertex 1 must be an array of 3 numbers, got an array of 2");
  EXPECT_EQ(error_of(with_vertices({{0, 0, 0}, {0, 0, 1}, 7})),
            prefix + "vertex 2 must be an array of 3 numbers, got integer");
  EXPECT_EQ(error_of(with_vertices({{0, 0, 0}, {0, "0", 1}, {1, 0, 0}})),
            prefix + "vertex 1 coordinate 1 must be a number, got string");
}

// ------------------------------------------------------------------------- geometry

TEST(SceneLoaderError, DegeneratePolygon) {
  const std::string prefix = "test.json: patch 1: field \"vertices\": degenerate polygon: ";
  EXPECT_EQ(error_of(with_vertices({{0, 0, 0}, {0, 0, 1}, {0, 0, 1}})),
            prefix + "vertices 1 and 2 coincide");
  EXPECT_EQ(error_of(with_vertices({{1, 0, 0}, {0, 0, 0}, {0, 0, 1}, {1, 0, 0}})),
            prefix + "vertices 3 and 0 coincide");
  EXPECT_EQ(error_of(with_vertices({{5, 5, 5}, {5, 5, 5}, {5, 5, 5}})),
            prefix + "vertices 0 and 1 coincide");
  EXPECT_EQ(error_of(with_vertices({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}})),
            prefix + "vertices 0, 1, 2 are (nearly) collinear, area 0 for diameter 2");
  // A sliver: area 5e-14 for diameter 1, below 1e-12 x diameter^2.
  EXPECT_EQ(error_of(with_vertices({{0, 0, 0}, {1, 0, 0}, {0.5, 0, 1e-13}}))
                .rfind(prefix + "vertices 0, 1, 2 are (nearly) collinear", 0),
            0u);
}

TEST(SceneLoaderError, NonPlanarQuad) {
  EXPECT_EQ(error_of(with_vertices({{0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0.5, 0}})),
            "test.json: patch 1: field \"vertices\": non-planar quadrilateral: vertex 3 is 0.5 "
            "from the plane of vertices 0, 1, 2 (tolerance 1.5e-06)");
  // Within the tolerance the quad is accepted.
  EXPECT_NO_THROW(
      parse_scene(with_vertices({{0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1e-7, 0}}).dump(), "t"));
}

TEST(SceneLoaderError, NonConvexQuad) {
  const std::string prefix =
      "test.json: patch 1: field \"vertices\": non-convex or self-intersecting quadrilateral: "
      "the corner at vertex ";
  const std::string suffix =
      " is reflex or straight (vertices must be counter-clockwise around a convex shape)";
  // A dart: vertex 3 pushed inside.
  EXPECT_EQ(error_of(with_vertices({{0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {0.25, 0, 0.5}})),
            prefix + "3" + suffix);
  // A bow-tie: vertices 2 and 3 swapped; corner 1 defines the normal, corner 2 turns back.
  EXPECT_EQ(error_of(with_vertices({{0, 0, 0}, {0, 0, 1}, {1, 0, 0}, {1, 0, 1}})),
            prefix + "2" + suffix);
  // A straight corner: vertex 3 on the segment from vertex 2 to vertex 0.
  EXPECT_EQ(error_of(with_vertices({{0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {0.5, 0, 0.5}})),
            prefix + "3" + suffix);
}

}  // namespace
}  // namespace ncube

// ------------------------------------------------- robustness (issue 8: no crash, no nonsense)
namespace ncube {
namespace {

std::string nested(int depth) { return std::string(depth, '[') + "1" + std::string(depth, ']'); }

TEST(SceneLoaderLimits, DeepNestingIsRejectedWithAShortMessage) {
  // nlohmann's dump() recursed once per level to show the value: 70,000 levels overflowed
  // the stack (and 50,000 gave a 100 KB message).
  std::string text = valid_scene().dump();
  text.replace(text.find("[2,3]"), 5, nested(70000));
  const std::string message = error_of_text(text);
  EXPECT_EQ(message, "test.json: patch 0: nested deeper than 16 arrays and objects (a scene needs 5)");
  EXPECT_EQ(error_of_text(nested(70000)).substr(0, 31), "test.json: nested deeper than 1");
}

TEST(SceneLoaderLimits, ValuesAndKeysInMessagesAreCutShort) {
  const std::string long_key = error_of(with_patch_field(0, std::string(1000000, 'x'), 1));
  EXPECT_LT(long_key.size(), 200u) << long_key.substr(0, 200);
  const std::string long_value = error_of(with_patch_field(0, "elements", std::string(1000000, 'x')));
  EXPECT_LT(long_value.size(), 200u) << long_value.substr(0, 200);
  // A key with a newline stays on one line (escaped as in JSON).
  const std::string newline = error_of(with_patch_field(0, "bad\nkey", 1));
  EXPECT_EQ(newline.find('\n'), std::string::npos) << newline;
  EXPECT_NE(newline.find("\"bad\\nkey\""), std::string::npos) << newline;
}

// An endless device is refused by what it is, before a byte is read (the limit while
// reading: tests/input_file_test.cpp).
TEST(SceneLoaderLimits, EndlessFileIsRefused) {
  try {
    load_scene("/dev/zero");
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()),
              "/dev/zero: scene file is a character device, not a regular file");
  }
}

TEST(SceneLoaderLimits, EmissionOutsideItsRangeIsRejected) {
  // 1e305 is finite, but the scene's emitted power overflowed and every radiosity came out
  // as null with status ok.
  EXPECT_EQ(error_of(with_patch_field(0, "emission", {1e305, 0, 0})),
            "test.json: patch 0: field \"emission\": channel 0 is 1e+305, must be 0 or in "
            "[1e-100, 1e100] (only ratios matter)");
  EXPECT_NE(error_of(with_patch_field(0, "emission", {0, 1e-300, 0})).find("channel 1 is 1e-300"),
            std::string::npos);
}

json scaled(json scene, double factor) {
  for (auto& patch : scene["patches"])
    for (auto& vertex : patch["vertices"])
      for (auto& c : vertex) c = c.get<double>() * factor;
  for (const char* key : {"eye", "look_at"})
    for (auto& c : scene["camera"][key]) c = c.get<double>() * factor;
  return scene;
}

TEST(SceneLoaderLimits, ScaledScenesAreAccepted) {
  // docs/scene-format.md: scaling a scene does not change its acceptance. Scenes far from
  // size 1 are brought to working units by a power of two; exact powers of two come out
  // exactly as the unscaled scene times a power of two.
  const Scene original = parse_scene(valid_scene().dump(), "test.json");
  for (double factor : {1e75, 1e-100, 1e150, 1e-150, 0x1p250, 0x1p-250}) {
    Scene scene;
    ASSERT_NO_THROW(scene = parse_scene(scaled(valid_scene(), factor).dump(), "test.json"))
        << factor;
    ASSERT_EQ(scene.elements.size(), original.elements.size());
    const double ratio = scene.patches[0].polygon[1].x / original.patches[0].polygon[1].x;
    EXPECT_LT(ratio, 1e5) << factor;  // brought near the original size
    EXPECT_GT(ratio, 1e-5) << factor;
    for (std::size_t p = 0; p < scene.patches.size(); ++p) {
      EXPECT_NEAR(glm::length(scene.patches[p].normal - original.patches[p].normal), 0.0, 1e-12);
      EXPECT_NEAR(scene.patches[p].area / original.patches[p].area, ratio * ratio, 1e-9 * ratio * ratio);
    }
    if (factor == 0x1p250 || factor == 0x1p-250) {
      for (std::size_t e = 0; e < scene.elements.size(); ++e)
        EXPECT_EQ(scene.elements[e].centre, ratio * original.elements[e].centre);
    }
  }
}

TEST(SceneLoaderLimits, OrdinaryScenesAreNotRescaled) {
  const Scene scene = parse_scene(scaled(valid_scene(), 1000.0).dump(), "test.json");
  EXPECT_EQ(scene.patches[0].polygon[1], Vec3(1000, 2000, 0));
}

TEST(SceneLoaderLimits, PatchesAndCameraFarOutOfScaleAreRejected) {
  json tiny = valid_scene();
  tiny["patches"][1]["vertices"] = {{0, 0, 0}, {0, 0, 1e-200}, {1e-200, 0, 0}};
  EXPECT_EQ(error_of(tiny), "test.json: patch 1: field \"vertices\": too small for the scene: its "
                            "diameter is less than 1e-12 of the scene's size");
  // An eye at 1e308 passed through a NaN comparison, and the renderer refused it only after
  // the result file was written.
  EXPECT_EQ(error_of(with_camera_field("eye", {1e308, 1e308, 1e308})),
            "test.json: field \"camera.eye\": too far from the scene: more than 1e12 times its size");
  json opposite = with_camera_field("eye", {1e308, 0, 0});
  opposite["camera"]["look_at"] = {-1e308, 0, 0};
  EXPECT_EQ(error_of(opposite),
            "test.json: field \"camera.look_at\": too far from camera.eye: their difference "
            "exceeds the largest double");
}

TEST(SceneLoaderLimits, ExtremeUpDirectionsAreDirections) {
  for (double size : {1e308, 1e-300}) {
    const Scene scene = parse_scene(with_camera_field("up", {0, size, 0}).dump(), "test.json");
    EXPECT_NEAR(glm::length(glm::normalize(scene.camera.up) - Vec3(0, 1, 0)), 0.0, 1e-15) << size;
  }
}

TEST(SceneLoaderLimits, ElementsCanBeBuiltLater) {
  Scene scene = parse_scene(valid_scene().dump(), "test.json", SceneElements::kLater);
  EXPECT_TRUE(scene.elements.empty());
  EXPECT_EQ(scene.element_total(), 10);
  EXPECT_DOUBLE_EQ(scene.patches[0].area, 1.0);
  scene.build_elements();
  EXPECT_EQ(scene.elements.size(), 10u);
}

}  // namespace
}  // namespace ncube

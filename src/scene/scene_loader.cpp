#include "scene/scene_loader.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <glm/geometric.hpp>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <vector>

#include "util/input_error.h"
#include "util/input_file.h"

namespace ncube {
namespace {

using json = nlohmann::json;

// Geometric tolerances, relative to the polygon's diameter d so that they do not depend on
// the scene's units: a length <= kTiny * d or an area <= kTiny * d^2 counts as zero; a
// vertex within kPlaneTolerance * d of a plane counts as on it.
constexpr double kTiny = 1e-12;
constexpr double kPlaneTolerance = 1e-6;
// |sin| of the angle between camera.up and the view direction below which they are parallel.
constexpr double kParallelTolerance = 1e-9;

// Where an error is: the message prefix, "<file>: " or "<file>: patch <i>: ".
struct Where {
  std::string prefix;

  [[noreturn]] void fail(const std::string& message) const { throw InputError(prefix + message); }
  [[noreturn]] void fail(const std::string& field, const std::string& message) const {
    fail("field \"" + field + "\": " + message);
  }
};

// Values in messages are shown as they were written (nlohmann prints the shortest number
// that reads back the same, and escapes control characters in strings), cut to
// kShownLength characters so that a message stays one short line whatever the input.
constexpr std::size_t kShownLength = 60;
std::string shown(const json& value) {
  std::string text = value.dump(-1, ' ', false, json::error_handler_t::replace);
  if (text.size() > kShownLength) text = text.substr(0, kShownLength) + "...";
  return text;
}
std::string shown_key(const std::string& key) { return shown(json(key)); }
std::string shown(double value) {
  std::ostringstream out;
  out.precision(6);
  out << value;
  return out.str();
}

std::string type_of(const json& value) {
  return value.is_number_integer() ? "integer" : value.is_number() ? "number" : value.type_name();
}

// Unknown keys are almost always typos of optional keys, which would otherwise be ignored
// silently; the message lists the keys that are allowed. Checked before the required keys,
// so that a misspelt required key is reported as the typo rather than as missing.
void reject_unknown_keys(const json& object, std::initializer_list<const char*> allowed,
                         const Where& where, const std::string& object_name = "") {
  for (const auto& item : object.items()) {
    bool known = false;
    std::string list;
    for (const char* key : allowed) {
      known = known || item.key() == key;
      list += (list.empty() ? "" : ", ") + std::string(key);
    }
    if (known) continue;
    const std::string message = "unknown key " + shown_key(item.key()) + " (allowed: " + list + ")";
    if (object_name.empty()) where.fail(message);
    where.fail(object_name, message);
  }
}

const json* optional_field(const json& object, const char* key) {
  const auto it = object.find(key);
  return it == object.end() ? nullptr : &*it;
}

const json& required_field(const json& object, const char* key, const Where& where,
                           const std::string& field) {
  const json* value = optional_field(object, key);
  if (!value) where.fail(field, "is missing (required)");
  return *value;
}

void require_object(const json& value, const Where& where, const std::string& field) {
  if (!value.is_object()) where.fail(field, "must be an object, got " + type_of(value));
}

// A finite JSON number. `label` names it inside its field ("channel 1", "vertex 2
// coordinate 0"), or is empty when the field itself is the number.
double finite_number(const json& value, const Where& where, const std::string& field,
                     const std::string& label) {
  const std::string item = label.empty() ? "" : label + " ";
  if (!value.is_number()) where.fail(field, item + "must be a number, got " + type_of(value));
  const double number = value.get<double>();
  // The parser already rejects overflowing literals such as 1e999; this keeps NaN and
  // infinity out even if that ever changes.
  if (!std::isfinite(number)) where.fail(field, item + "must be a finite number");
  return number;
}

// An array of 3 finite numbers, whose entries are called `entry` ("channel", "coordinate").
// `label` names the array inside its field ("vertex 2") or is empty.
Vec3 vec3(const json& value, const Where& where, const std::string& field, const std::string& entry,
          const std::string& label = "") {
  const std::string item = label.empty() ? "" : label + " ";
  if (!value.is_array() || value.size() != 3)
    where.fail(field, item + "must be an array of 3 numbers, got " +
                          (value.is_array() ? "an array of " + std::to_string(value.size())
                                            : type_of(value)));
  Vec3 result;
  for (int i = 0; i < 3; ++i)
    result[i] = finite_number(value[i], where, field, item + entry + " " + std::to_string(i));
  return result;
}

// ---------------------------------------------------------------------------- parsing

// nlohmann's message without its "[json.exception.parse_error.101] parse error at line 1,
// column 6: " preamble: the loader prints its own position.
std::string bare_message(std::string message) {
  const auto bracket = message.find("] ");
  if (message.rfind("[json.exception.", 0) == 0 && bracket != std::string::npos)
    message.erase(0, bracket + 2);
  if (message.rfind("parse error", 0) == 0) {
    const auto colon = message.find(": ");
    if (colon != std::string::npos) message.erase(0, colon + 2);
  }
  return message;
}

// A first pass over the text through nlohmann's SAX interface, in time linear in its size,
// before the document is built:
// - duplicate keys are rejected: JSON allows them and nlohmann keeps the last, which would
//   silently drop the first value. The pass follows the top-level key and the index in
//   "patches" to name the patch in messages.
// - nesting deeper than kMaxNestingDepth is rejected: a scene needs 5 levels, and some of
//   nlohmann's functions (dump, comparisons) recurse once per level.
// - a syntax error is located (nlohmann's exceptions for overflowing numbers such as 1e999
//   carry no position; the SAX error handler receives the position of every kind).
// (A parser callback could check keys too, but nlohmann's callback parser scans the
// enclosing array after every element it closes, which made loading quadratic in the
// number of patches.)
class FirstPass : public json::json_sax_t {
 public:
  explicit FirstPass(const std::string& path) : path_(path) {}

  bool null() override { return value(); }
  bool boolean(bool) override { return value(); }
  bool number_integer(number_integer_t) override { return value(); }
  bool number_unsigned(number_unsigned_t) override { return value(); }
  bool number_float(number_float_t, const string_t&) override { return value(); }
  bool string(string_t&) override { return value(); }
  bool binary(binary_t&) override { return value(); }
  bool start_object(std::size_t) override {
    open(true);
    return true;
  }
  bool end_object() override {
    containers_.pop_back();
    keys_.pop_back();
    return true;
  }
  bool start_array(std::size_t) override {
    open(false);
    return true;
  }
  bool end_array() override {
    containers_.pop_back();
    return true;
  }
  bool key(string_t& key) override {
    if (containers_.size() == 1) top_key_ = key;
    if (!keys_.back().insert(key).second) {
      const std::string where = containers_.size() == 1 ? ""
                                : in_patches()          ? "patch " + std::to_string(patch_) + ": "
                                                        : "field \"" + top_key_ + "\": ";
      throw InputError(path_ + ": " + where + "duplicate key " + shown_key(key) +
                       " (each key may appear once per object)");
    }
    return true;
  }
  bool parse_error(std::size_t position, const std::string&,
                   const json::exception& error) override {
    error_byte_ = position;
    error_message_ = bare_message(error.what());
    return false;
  }

  bool failed() const { return !error_message_.empty(); }
  // "<line>:<column>: malformed JSON: <message>", line and column 1-based, column in bytes.
  [[noreturn]] void fail_malformed(const std::string& text) const {
    const std::size_t index = error_byte_ > 0 ? std::min(error_byte_ - 1, text.size()) : 0;
    std::size_t line = 1, line_start = 0;
    for (std::size_t i = 0; i < index; ++i)
      if (text[i] == '\n') ++line, line_start = i + 1;
    throw InputError(path_ + ":" + std::to_string(line) + ":" +
                     std::to_string(index - line_start + 1) +
                     ": malformed JSON: " + error_message_);
  }

 private:
  bool in_patches() const {
    return containers_.size() >= 2 && top_key_ == "patches" && !containers_[1];
  }
  // Every value directly inside "patches", whatever its type, is the next patch.
  void item_starts() {
    if (containers_.size() == 2 && in_patches()) patch_ = items_in_patches_++;
  }
  bool value() {
    item_starts();
    return true;
  }
  void open(bool object) {
    item_starts();
    if (containers_.size() >= std::size_t(kMaxNestingDepth))
      throw InputError(path_ + ": " +
                       (containers_.size() >= 2 && in_patches() ? "patch " + std::to_string(patch_) + ": " : "") +
                       "nested deeper than " + std::to_string(kMaxNestingDepth) +
                       " arrays and objects (a scene needs 5)");
    containers_.push_back(object);
    if (object) keys_.emplace_back();
  }

  std::string path_;
  std::vector<bool> containers_;  // the open arrays (false) and objects (true), outermost first
  std::vector<std::set<std::string>> keys_;  // keys seen in each open object
  std::string top_key_;
  int items_in_patches_ = 0;
  int patch_ = 0;  // index of the patch being read
  std::size_t error_byte_ = 0;  // 1-based offset of the offending character
  std::string error_message_;
};

json parse_json(const std::string& text, const std::string& path) {
  FirstPass first(path);
  json::sax_parse(text, &first);
  if (first.failed()) first.fail_malformed(text);
  return json::parse(text);
}

// --------------------------------------------------------------------------- validation

double max_component(const Vec3& v) {
  return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
}

// `v` scaled by a power of two (exactly) so that its largest component is in [0.5, 1).
Vec3 in_own_units(const Vec3& v) {
  int exponent = 0;
  std::frexp(max_component(v), &exponent);
  return Vec3(std::ldexp(v.x, -exponent), std::ldexp(v.y, -exponent), std::ldexp(v.z, -exponent));
}

Camera parse_camera(const json& value, const Where& where) {
  require_object(value, where, "camera");
  reject_unknown_keys(value, {"eye", "look_at", "up", "fov_deg"}, where, "camera");
  const auto point = [&](const char* key) {
    const std::string field = std::string("camera.") + key;
    return vec3(required_field(value, key, where, field), where, field, "coordinate");
  };
  Camera camera;
  camera.eye = point("eye");
  camera.look_at = point("look_at");
  camera.up = point("up");
  const json& fov = required_field(value, "fov_deg", where, "camera.fov_deg");
  camera.fov_deg = finite_number(fov, where, "camera.fov_deg", "");
  if (!(camera.fov_deg > 0.0 && camera.fov_deg < 180.0))
    where.fail("camera.fov_deg", "is " + shown(fov) + ", must be in (0, 180)");
  const Vec3 view = camera.look_at - camera.eye;
  if (!std::isfinite(view.x) || !std::isfinite(view.y) || !std::isfinite(view.z))
    where.fail("camera.look_at", "too far from camera.eye: their difference exceeds the largest double");
  if (view == Vec3(0.0))
    where.fail("camera.look_at", "equals camera.eye, so there is no view direction");
  if (camera.up == Vec3(0.0)) where.fail("camera.up", "must not be the zero vector");
  // Directions are compared in units of their largest component, so that no length
  // overflows or underflows; `up` is kept in such units when it is extreme (the renderer
  // normalises it).
  if (!(max_component(camera.up) > 1e-100 && max_component(camera.up) < 1e100))
    camera.up = in_own_units(camera.up);
  if (glm::length(glm::cross(glm::normalize(in_own_units(view)), glm::normalize(in_own_units(camera.up)))) <=
      kParallelTolerance)
    where.fail("camera.up", "is parallel to the view direction (look_at - eye)");
  return camera;
}

Rgb parse_colour(const json& value, const Where& where, const std::string& field, bool below_one) {
  const Rgb colour = vec3(value, where, field, "channel");
  for (int i = 0; i < 3; ++i) {
    const bool ok = colour[i] >= 0.0 && (!below_one || colour[i] < 1.0);
    if (!ok)
      where.fail(field, "channel " + std::to_string(i) + " is " + shown(value[i]) +
                            (below_one ? ", must be in [0, 1)" : ", must be >= 0"));
  }
  return colour;
}

// One subdivision count; JSON integers only (2.0 is rejected: counts are written as counts).
long subdivision(const json& value, const Where& where, const char* name) {
  const std::string item = std::string(name) + " ";
  if (!value.is_number_integer())
    where.fail("elements", item + "must be an integer, got " + shown(value));
  const bool too_large = value.is_number_unsigned()
                             ? value.get<std::uint64_t>() > std::uint64_t(kMaxElementsPerPatch)
                             : value.get<std::int64_t>() > kMaxElementsPerPatch;
  if (too_large)
    where.fail("elements", item + "is " + shown(value) + ", absurdly large (limit " +
                               std::to_string(kMaxElementsPerPatch) + " elements per patch)");
  if (value.get<std::int64_t>() < 1)
    where.fail("elements", item + "is " + shown(value) + ", must be >= 1");
  return long(value.get<std::int64_t>());
}

// The largest absolute coordinate difference between two vertices, as a power of two:
// the polygon is checked in units of it, so that no square or cross product of lengths
// overflows or underflows whatever the scene's units (docs/scene-format.md, "Conventions").
// Returns false when a difference overflows (vertices more than ~1.8e308 apart).
bool polygon_unit(const std::vector<Vec3>& v, int& exponent) {
  double largest = 0.0;
  for (const Vec3& a : v)
    for (const Vec3& b : v)
      for (int axis = 0; axis < 3; ++axis) largest = std::max(largest, std::abs(a[axis] - b[axis]));
  if (!std::isfinite(largest)) return false;
  exponent = 0;
  if (largest > 0.0) std::frexp(largest, &exponent);
  return true;
}

// The rules of docs/scene-format.md, "Geometry": no coincident neighbours, non-zero area,
// planar and strictly convex, with the normal of (v0, v1, v2) as the front. The tests run
// on the vertices relative to v0 in units of a power of two near the polygon's size (exact
// scalings), so they accept the same polygons at every scale; lengths in messages are in
// the file's units.
void check_geometry(const std::vector<Vec3>& vertices, const Where& where) {
  int exponent = 0;
  if (!polygon_unit(vertices, exponent))
    where.fail("vertices", "coordinates too far apart: a difference between two of them "
                           "exceeds the largest double");
  const double unit = std::ldexp(1.0, exponent);  // one unit of the scaled coordinates
  std::vector<Vec3> v;
  for (const Vec3& x : vertices)
    v.push_back(Vec3(std::ldexp(x.x - vertices[0].x, -exponent),
                     std::ldexp(x.y - vertices[0].y, -exponent),
                     std::ldexp(x.z - vertices[0].z, -exponent)));
  const int n = int(v.size());
  double diameter = 0.0;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) diameter = std::max(diameter, glm::length(v[i] - v[j]));
  const double tiny_area = kTiny * diameter * diameter;

  for (int i = 0; i < n; ++i) {
    const int next = (i + 1) % n;
    if (!(glm::length(v[next] - v[i]) > kTiny * diameter))
      where.fail("vertices", "degenerate polygon: vertices " + std::to_string(i) + " and " +
                                 std::to_string(next) + " coincide");
  }
  // Triangle (v0, v1, v2) defines the normal, so it must have an area even for a quad.
  const Vec3 cross012 = glm::cross(v[1] - v[0], v[2] - v[0]);
  if (!(0.5 * glm::length(cross012) > tiny_area))
    where.fail("vertices", "degenerate polygon: vertices 0, 1, 2 are (nearly) collinear, area " +
                               shown(0.5 * glm::length(cross012) * unit * unit) +
                               " for diameter " + shown(diameter * unit));
  if (n == 3) return;

  const Vec3 normal = glm::normalize(cross012);
  const double off_plane = std::abs(glm::dot(v[3] - v[0], normal));
  if (!(off_plane <= kPlaneTolerance * diameter))
    where.fail("vertices", "non-planar quadrilateral: vertex 3 is " + shown(off_plane * unit) +
                               " from the plane of vertices 0, 1, 2 (tolerance " +
                               shown(kPlaneTolerance * diameter * unit) + ")");
  // Every corner must turn the same way as corner 1 (which defines the normal); a reflex
  // corner or a bow-tie makes some corner turn against it.
  for (int i = 0; i < n; ++i) {
    const Vec3 turn = glm::cross(v[i] - v[(i + n - 1) % n], v[(i + 1) % n] - v[i]);
    if (!(glm::dot(turn, normal) > tiny_area))
      where.fail("vertices",
                 "non-convex or self-intersecting quadrilateral: the corner at vertex " +
                     std::to_string(i) +
                     " is reflex or straight (vertices must be counter-clockwise "
                     "around a convex shape)");
  }
}

Patch parse_patch(const json& value, const Where& where, long& scene_elements) {
  if (!value.is_object()) where.fail("must be an object, got " + type_of(value));
  reject_unknown_keys(value, {"vertices", "reflectance", "emission", "elements"}, where);

  const json& vertices = required_field(value, "vertices", where, "vertices");
  if (!vertices.is_array() || (vertices.size() != 3 && vertices.size() != 4))
    where.fail("vertices",
               "must be an array of 3 or 4 vertices, got " +
                   (vertices.is_array() ? "an array of " + std::to_string(vertices.size())
                                        : type_of(vertices)));
  std::vector<Vec3> v;
  for (std::size_t i = 0; i < vertices.size(); ++i)
    v.push_back(vec3(vertices[i], where, "vertices", "coordinate", "vertex " + std::to_string(i)));
  check_geometry(v, where);

  Patch patch;
  patch.polygon =
      v.size() == 3 ? Polygon::triangle(v[0], v[1], v[2]) : Polygon::quad(v[0], v[1], v[2], v[3]);
  patch.reflectance = parse_colour(required_field(value, "reflectance", where, "reflectance"),
                                   where, "reflectance", true);
  if (const json* emission = optional_field(value, "emission"))
    patch.emission = parse_colour(*emission, where, "emission", false);
  for (int i = 0; i < 3; ++i)
    if (patch.emission[i] != 0.0 &&
        !(patch.emission[i] >= kMinEmission && patch.emission[i] <= kMaxEmission))
      where.fail("emission", "channel " + std::to_string(i) + " is " +
                                 shown((*optional_field(value, "emission"))[i]) +
                                 ", must be 0 or in [1e-100, 1e100] (only ratios matter)");

  if (const json* elements = optional_field(value, "elements")) {
    if (!elements->is_array() || elements->size() != 2)
      where.fail("elements", "must be an array [nu, nv] of 2 integers, got " + shown(*elements));
    const long nu = subdivision((*elements)[0], where, "nu");
    const long nv = subdivision((*elements)[1], where, "nv");
    if (nu * nv > kMaxElementsPerPatch)
      where.fail("elements", std::to_string(nu) + " x " + std::to_string(nv) + " = " +
                                 std::to_string(nu * nv) + " elements, absurdly large (limit " +
                                 std::to_string(kMaxElementsPerPatch) + " per patch)");
    patch.nu = int(nu);
    patch.nv = int(nv);
  }
  scene_elements += patch.element_count();
  if (scene_elements > kMaxElementsPerScene)
    where.fail("elements", "brings the scene to " + std::to_string(scene_elements) +
                               " elements, absurdly large (limit " +
                               std::to_string(kMaxElementsPerScene) + " per scene)");
  return patch;
}

// A patch's diameter, the largest distance between two of its vertices.
double diameter(const Polygon& polygon) {
  double d = 0.0;
  for (int i = 0; i < polygon.count; ++i)
    for (int j = i + 1; j < polygon.count; ++j) d = std::max(d, glm::length(polygon[i] - polygon[j]));
  return d;
}

// Units are arbitrary (docs/scene-format.md, "Conventions"): a scene whose bounding box is
// far from size 1 is scaled by a power of two, which is exact in floating point, so that
// the simulation's products of lengths neither overflow nor underflow. Scenes of ordinary
// size are left as written. Then every patch must be at least kTiny of the scene's size,
// and the camera within 1 / kTiny scene sizes of it: beyond these ratios lengths are lost
// in rounding.
void bring_to_working_units(Scene& scene, bool has_camera, const std::string& path) {
  const Where top{path + ": "};
  const Bounds bounds = scene_bounds(scene);
  const Vec3 extent = bounds.hi - bounds.lo;
  const double largest = max_component(extent);
  if (!std::isfinite(largest))
    top.fail("patches", "the scene spans more than the largest double");
  int exponent = 0;
  std::frexp(largest, &exponent);
  if (exponent < kSmallestUnscaledExponent || exponent > kLargestUnscaledExponent) {
    const auto scale = [exponent](Vec3& v) {
      v = Vec3(std::ldexp(v.x, -exponent), std::ldexp(v.y, -exponent), std::ldexp(v.z, -exponent));
    };
    for (Patch& patch : scene.patches)
      for (Vec3& v : patch.polygon.vertices) scale(v);
    if (has_camera) {
      scale(scene.camera.eye);
      scale(scene.camera.look_at);
    }
  }
  const double size = scene_bounds(scene).diagonal();
  for (std::size_t i = 0; i < scene.patches.size(); ++i) {
    const double d = diameter(scene.patches[i].polygon);
    if (!(d > kTiny * size))
      Where{path + ": patch " + std::to_string(i) + ": "}.fail(
          "vertices", "too small for the scene: its diameter is less than 1e-12 of the "
                      "scene's size");
  }
  if (!has_camera) return;
  const Bounds scaled = scene_bounds(scene);
  const Vec3 centre = 0.5 * (scaled.lo + scaled.hi);
  for (const auto& [field, point] : {std::pair{"camera.eye", scene.camera.eye},
                                     std::pair{"camera.look_at", scene.camera.look_at}})
    if (!(max_component(point - centre) <= size / kTiny))
      top.fail(field, "too far from the scene: more than 1e12 times its size");
}

}  // namespace

Scene parse_scene(const std::string& text, const std::string& path, SceneElements elements) {
  return scene_from_document(parse_json(text, path), path, elements);
}

Scene scene_from_document(const json& root, const std::string& path, SceneElements elements) {
  const Where top{path + ": "};
  if (!root.is_object()) top.fail("the scene must be a JSON object, got " + type_of(root));
  reject_unknown_keys(root, {"name", "camera", "patches"}, top);

  Scene scene;
  const json& name = required_field(root, "name", top, "name");
  if (!name.is_string()) top.fail("name", "must be a string, got " + type_of(name));
  scene.name = name.get<std::string>();
  if (scene.name.empty()) top.fail("name", "must not be empty");

  const json* camera = optional_field(root, "camera");
  if (camera) scene.camera = parse_camera(*camera, top);

  const json& patches = required_field(root, "patches", top, "patches");
  if (!patches.is_array()) top.fail("patches", "must be an array, got " + type_of(patches));
  if (patches.empty()) top.fail("patches", "is empty; a scene needs at least one patch");
  long scene_elements = 0;
  bool emits = false;
  scene.patches.reserve(patches.size());
  for (std::size_t i = 0; i < patches.size(); ++i) {
    scene.patches.push_back(parse_patch(
        patches[i], Where{path + ": patch " + std::to_string(i) + ": "}, scene_elements));
    const Rgb& e = scene.patches.back().emission;
    emits = emits || e.r > 0.0 || e.g > 0.0 || e.b > 0.0;
  }
  if (!emits) top.fail("patches", "no patch has a non-zero \"emission\"; a scene needs a light");
  bring_to_working_units(scene, camera != nullptr, path);

  if (elements == SceneElements::kBuild)
    scene.build_elements();
  else
    scene.derive_patch_fields();
  if (!camera) scene.camera = default_camera(scene);
  return scene;
}

Scene load_scene(const std::string& path, SceneElements elements) {
  if (path.empty()) throw InputError("the scene file name is empty");
  return parse_scene(read_input_file(path, kSceneFile), path, elements);
}

}  // namespace ncube

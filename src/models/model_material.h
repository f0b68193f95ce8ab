// A model's materials as reflectance and emission (docs/scene-format.md, "Importing models"):
// Assimp's numbers read back as the file wrote them, each colour checked (never a silent
// clamp), and --light NAME[=R,G,B] for models whose lights are not marked in the file.
#pragma once

#include <string>
#include <vector>

#include <glm/vec3.hpp>

struct aiMaterial;

namespace ncube::models {

using Point = glm::dvec3;

// A material without a diffuse or base colour: mid grey.
constexpr double kDefaultReflectance = 0.5;

struct Material {
  Point reflectance{kDefaultReflectance};
  Point emission{0.0};
};

// The number the file wrote, from the float Assimp holds (0.6, not 0.60000002384).
double as_written(float value);
Point as_written(float x, float y, float z);

// "x y z", for messages.
std::string show(const Point& p);

// Reflectance from the glTF base colour or the MTL Kd (kDefaultReflectance when the file does
// not give it: `colour_given` false), emission from the emissive colour or Ke. Throws
// InputError naming `where` and the field when a value is out of range.
Material read_material(const aiMaterial& m, const std::string& where, bool colour_given);

// Whether one of `lights` (NAME or NAME=R,G,B) names `name`; sets `emission` (1, 1, 1 without
// values) and marks it in `used`. Throws InputError on values that are not finite and >= 0.
bool light_for(const std::vector<std::string>& lights, const std::string& name, Point& emission,
               std::vector<bool>& used);

}  // namespace ncube::models

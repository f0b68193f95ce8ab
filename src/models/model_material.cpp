#include "models/model_material.h"

#include <assimp/material.h>

#include <charconv>
#include <cmath>
#include <sstream>

#include "util/input_error.h"

namespace ncube::models {

// Assimp holds numbers as floats: 0.6 in a file arrives as 0.60000002384. The shortest
// decimal that reads back as that float is what the file said (as written by any tool that
// wrote it from a float or by hand), and read as a double it is the file's own number, so a
// model gives the same scene as the JSON written with the same numbers.
double as_written(float value) {
  char text[32];
  const auto [end, error] = std::to_chars(text, text + sizeof text, value);
  if (error != std::errc()) return double(value);
  double result = 0.0;
  std::from_chars(text, end, result);
  return result;
}

Point as_written(float x, float y, float z) { return Point(as_written(x), as_written(y), as_written(z)); }

std::string show(const Point& p) {
  std::ostringstream text;
  text << p.x << " " << p.y << " " << p.z;
  return text.str();
}

// A material's reflectance and emission, checked: never a silent clamp.
Material read_material(const aiMaterial& m, const std::string& where, bool colour_given) {
  Material result;
  aiColor4D colour;
  if (colour_given && (m.Get(AI_MATKEY_BASE_COLOR, colour) == aiReturn_SUCCESS ||
                       m.Get(AI_MATKEY_COLOR_DIFFUSE, colour) == aiReturn_SUCCESS))
    result.reflectance = as_written(colour.r, colour.g, colour.b);
  aiColor3D emissive;
  if (m.Get(AI_MATKEY_COLOR_EMISSIVE, emissive) == aiReturn_SUCCESS)
    result.emission = as_written(emissive.r, emissive.g, emissive.b);
  for (int c = 0; c < 3; ++c) {
    if (!(result.reflectance[c] >= 0.0 && result.reflectance[c] < 1.0))
      throw InputError(where + ": reflectance (Kd, base colour) " + show(result.reflectance) +
                       ": each channel must be in [0, 1) (1 would never lose energy)");
    if (!(result.emission[c] >= 0.0) || !std::isfinite(result.emission[c]))
      throw InputError(where + ": emission (Ke, emissive) " + show(result.emission) +
                       ": each channel must be finite and not negative");
  }
  return result;
}

// --light NAME[=R,G,B]: the emission it gives the material or mesh called NAME.
// `used` notes each --light that named something: one that names nothing (a typing error)
// is refused after the model is read, not ignored.
bool light_for(const std::vector<std::string>& lights, const std::string& name, Point& emission,
               std::vector<bool>& used) {
  for (std::size_t k = 0; k < lights.size(); ++k) {
    const std::string& light = lights[k];
    const std::size_t equals = light.find('=');
    if (light.substr(0, equals) != name) continue;
    used[k] = true;
    emission = Point(1.0);
    if (equals != std::string::npos) {
      std::istringstream values(light.substr(equals + 1));
      char comma1 = 0, comma2 = 0;
      if (!(values >> emission.r >> comma1 >> emission.g >> comma2 >> emission.b) ||
          comma1 != ',' || comma2 != ',' || !values.eof() || !(emission.r >= 0) ||
          !(emission.g >= 0) || !(emission.b >= 0) || !std::isfinite(emission.r + emission.g + emission.b))
        throw InputError("--light " + light + ": expected NAME or NAME=R,G,B with finite R, G, B >= 0");
    }
    return true;
  }
  return false;
}

}  // namespace ncube::models

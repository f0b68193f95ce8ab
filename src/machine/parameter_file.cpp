#include "machine/parameter_file.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "util/input_error.h"
#include "util/input_file.h"

namespace ncube {

std::string value_problem(const ParameterSpec& spec, double value, const std::string& written) {
  if (!std::isfinite(value)) return "value is not finite";
  if (value < spec.min_value)
    return "value " + written + " is below " + nlohmann::json(spec.min_value).dump();
  if (value > spec.max_value)
    return "value " + written + " is above " + nlohmann::json(spec.max_value).dump();
  if (spec.integer && value != std::floor(value))
    return "value " + written + " must be a whole number";
  return "";
}

std::map<std::string, double> read_parameter_file(const std::string& path, const InputKind& kind,
                                                  const std::vector<ParameterSpec>& specs,
                                                  const std::vector<std::string>& sections) {
  // A parameter file is a few kilobytes; the limit stops a wrong path such as /dev/zero.
  const std::string text = read_input_file(path, kind);
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    throw InputError(path + ": malformed JSON at byte " + std::to_string(e.byte));
  }
  if (!doc.is_object() || !doc.contains("parameters") || !doc["parameters"].is_object())
    throw InputError(path + ": expected an object with a \"parameters\" object");
  for (auto it = doc.begin(); it != doc.end(); ++it)
    if (it.key() != "description" && it.key() != "parameters" &&
        std::find(sections.begin(), sections.end(), it.key()) == sections.end())
      throw InputError(path + ": unknown key \"" + it.key() + "\"");
  const nlohmann::json& parameters = doc["parameters"];
  std::map<std::string, double> values;
  for (const ParameterSpec& spec : specs) {
    const std::string where = path + ": parameter \"" + spec.name + "\"";
    if (!parameters.contains(spec.name)) {
      if (spec.optional) continue;
      throw InputError(where + ": missing");
    }
    const nlohmann::json& entry = parameters[spec.name];
    if (!entry.is_object() || !entry.contains("value") || !entry["value"].is_number())
      throw InputError(where + ": expected {\"value\": <number>, ...}");
    for (auto it = entry.begin(); it != entry.end(); ++it)
      if (it.key() != "value" && it.key() != "unit" && it.key() != "doc" && it.key() != "source")
        throw InputError(where + ": unknown key \"" + it.key() + "\"");
    if (spec.unit && entry.contains("unit") &&
        (!entry["unit"].is_string() || entry["unit"].get<std::string>() != spec.unit))
      throw InputError(where + ": unit " + entry["unit"].dump() + " is not \"" + spec.unit +
                       "\", the unit the simulator reads it in");
    const double value = entry["value"].get<double>();
    const std::string problem = value_problem(spec, value, entry["value"].dump());
    if (!problem.empty()) throw InputError(where + ": " + problem);
    values[spec.name] = value;
  }
  for (auto it = parameters.begin(); it != parameters.end(); ++it) {
    bool known = false;
    for (const ParameterSpec& spec : specs) known = known || spec.name == it.key();
    if (!known) throw InputError(path + ": unknown parameter \"" + it.key() + "\"");
  }
  return values;
}

}  // namespace ncube

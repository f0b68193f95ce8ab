#include "machine/platform_config.h"

#include <nlohmann/json.hpp>

#include "machine/parameter_file.h"
#include "machine/simgrid_platform_file.h"
#include "machine/simgrid_setting_ranges.h"
#include "machine/simgrid_settings.h"
#include "util/input_error.h"
#include "util/input_file.h"

namespace ncube {
namespace {

std::map<std::string, std::string> read_simgrid_config(const std::string& path) {
  // Already checked by the reader.
  const nlohmann::json doc = nlohmann::json::parse(read_input_file(path, kPlatformFile));
  if (!doc.contains("simgrid_config")) return default_network_model();
  const nlohmann::json& section = doc["simgrid_config"];
  if (!section.is_object()) throw InputError(path + ": \"simgrid_config\": expected an object");
  std::map<std::string, std::string> settings;
  std::vector<std::string> keys, arguments;
  // SimGrid would end the process on a setting it refuses (src/machine/simgrid_settings.h):
  // it is asked about the settings so far, in one child.
  const auto check_so_far = [&] {
    if (const SettingRefusal refused = simgrid_refusal_of(arguments); refused.index < keys.size())
      throw InputError(path + ": \"simgrid_config\": \"" + keys[refused.index] + "\": " +
                       refused.problem);
  };
  for (auto it = section.begin(); it != section.end(); ++it) {
    if (!it.value().is_string())
      throw InputError(path + ": \"simgrid_config\": \"" + it.key() + "\": expected a string");
    settings[it.key()] = it.value().get<std::string>();
    // A platform file never names a file to write (src/machine/simgrid_setting_ranges.h).
    std::string problem = platform_setting_problem(it.key(), settings[it.key()]);
    const std::string argument = "--cfg=" + it.key() + ":" + settings[it.key()];
    if (problem.empty()) problem = simgrid_setting_form_problem(argument);
    if (!problem.empty()) {
      check_so_far();  // one SimGrid refuses before this one is named first, as one by one
      throw InputError(path + ": \"simgrid_config\": \"" + it.key() + "\": " + problem);
    }
    keys.push_back(it.key());
    arguments.push_back(argument);
  }
  check_so_far();
  return settings;
}

}  // namespace

PlatformConfig load_platform_config(const std::string& path,
                                    const std::vector<std::string>& simgrid_arguments) {
  if (is_simgrid_platform_file(path)) return read_simgrid_platform_file(path, simgrid_arguments);
  std::vector<ParameterSpec> specs;
  for (const MachineParameter& p : machine_parameters()) specs.push_back(parameter_spec(p));
  const auto values = read_parameter_file(path, kPlatformFile, specs, {"simgrid_config"});
  PlatformConfig c;
  for (const MachineParameter& p : machine_parameters())
    if (values.count(p.name)) p.set(c, values.at(p.name));  // an optional one left out: 0
  c.simgrid_config = read_simgrid_config(path);
  return c;
}

}  // namespace ncube

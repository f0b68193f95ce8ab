#include "machine/platform_config.h"

#include <nlohmann/json.hpp>

#include "machine/parameter_file.h"
#include "machine/simgrid_platform_file.h"
#include "machine/simgrid_settings.h"
#include "util/input_error.h"
#include "util/input_file.h"

namespace ncube {
namespace {

std::map<std::string, std::string> read_simgrid_config(const std::string& path) {
  // Already checked by the reader.
  const nlohmann::json doc = nlohmann::json::parse(read_input_file(path, kPlatformFile));
  if (!doc.contains("simgrid_config")) return PlatformConfig{}.simgrid_config;
  const nlohmann::json& section = doc["simgrid_config"];
  if (!section.is_object()) throw InputError(path + ": \"simgrid_config\": expected an object");
  std::map<std::string, std::string> settings;
  for (auto it = section.begin(); it != section.end(); ++it) {
    if (!it.value().is_string())
      throw InputError(path + ": \"simgrid_config\": \"" + it.key() + "\": expected a string");
    settings[it.key()] = it.value().get<std::string>();
    // SimGrid would end the process on a setting it refuses (src/machine/simgrid_settings.h).
    const std::string problem =
        simgrid_setting_problem("--cfg=" + it.key() + ":" + settings[it.key()]);
    if (!problem.empty())
      throw InputError(path + ": \"simgrid_config\": \"" + it.key() + "\": " + problem);
  }
  return settings;
}

}  // namespace

PlatformConfig load_platform_config(const std::string& path,
                                    const std::vector<std::string>& simgrid_arguments) {
  if (is_simgrid_platform_file(path)) return read_simgrid_platform_file(path, simgrid_arguments);
  const auto v = read_parameter_file(path, kPlatformFile,
                                     // Sanity bounds, far around the nCube2's values: within
                                     // them every simulated time stays finite and well inside
                                     // the range SimGrid computes with (docs/model.md, "Machine").
                                     {{"dimension", 0, true, 13},
                                      {"node_speed", 1e3, false, 1e15},
                                      {"node_memory", 1, true, 0x1p50},
                                      {"link_bandwidth", 1e3, false, 1e15},
                                      {"hop_latency", 0, false, 1},
                                      {"send_overhead", 0, false, 1},
                                      {"receive_overhead", 0, false, 1}},
                                     {"simgrid_config"});
  PlatformConfig c;
  c.dimension = int(v.at("dimension"));
  c.node_speed = v.at("node_speed");
  c.node_memory = v.at("node_memory");
  c.link_bandwidth = v.at("link_bandwidth");
  c.hop_latency = v.at("hop_latency");
  c.send_overhead = v.at("send_overhead");
  c.receive_overhead = v.at("receive_overhead");
  c.simgrid_config = read_simgrid_config(path);
  return c;
}

}  // namespace ncube

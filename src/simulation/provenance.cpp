#include "simulation/provenance.h"

#include "machine/machine_parameters.h"
#include "simulation/result_file.h"
#include "models/model_import.h"
#include "util/input_file.h"
#include "util/version.h"

namespace ncube {

nlohmann::json platform_values(const PlatformConfig& p) {
  // A SimGrid XML file's interconnect is the file's (its hash names it): only the values it
  // gives are written (src/machine/machine_parameters.h, carried_by).
  nlohmann::json values = {{"nodes", p.node_count()}};
  // An optional parameter the file left out (0) is not listed: a machine that gives only
  // node_speed keeps the values it had before the rates per kind of work existed.
  for (const MachineParameter& m : machine_parameters())
    if (carried_by(m, p.format) && !(m.optional && m.get(p) == 0))
      values[m.name] = m.integral ? nlohmann::json(static_cast<long long>(m.get(p)))
                                  : nlohmann::json(m.get(p));
  return values;
}

nlohmann::json cost_model_values(const CostModel& c) {
  nlohmann::json values = nlohmann::json::object();
  for (const CostParameter& p : cost_parameters()) values[p.name] = c.*p.field;
  return values;
}

namespace {

const InputKind& scene_kind(const std::string& file) {
  return is_model_file(file) ? kModelFile : kSceneFile;
}

const InputKind& platform_kind(const PlatformConfig& platform) {
  return platform.format == "simgrid-xml" ? kSimgridPlatformFile : kPlatformFile;
}

}  // namespace

nlohmann::json input_listing(const RunInputs& inputs, const PlatformConfig& platform) {
  const auto entry = [](const char* role, const std::string& file, const InputKind& kind) {
    return nlohmann::json{{"role", role}, {"file", file}, {"sha256", input_sha256(file, kind)}};
  };
  const bool model = is_model_file(inputs.scene_file);
  nlohmann::json list = {entry(model ? "model" : "scene", inputs.scene_file, scene_kind(inputs.scene_file))};
  for (const std::string& part : inputs.scene_parts) list.push_back(entry("model part", part, kModelPart));
  list.push_back(entry("platform", inputs.platform_file, platform_kind(platform)));
  list.push_back(entry("cost model", inputs.cost_model_file, kCostModelFile));
  return {{"inputs", list}};
}

nlohmann::json provenance_to_json(const RunInputs& inputs, const Scene& scene,
                                  const PlatformConfig& platform, const CostModel& costs,
                                  const SimulationResult& result) {
  // Each file hashed through the gate that read it, with its kind's limit (util/input_file.h).
  nlohmann::json platform_json = {{"file", inputs.platform_file},
                                  {"sha256", input_sha256(inputs.platform_file, platform_kind(platform))},
                                  {"format", platform.format},
                                  {"values", platform_values(platform)},
                                  {"simgrid_config", result.simgrid_config}};
  nlohmann::json scene_json = {{"name", scene.name},
                               {"file", inputs.scene_file},
                               {"sha256", input_sha256(inputs.scene_file, scene_kind(inputs.scene_file))}};
  // Only a model has parts: a scene file's provenance stays as it was.
  for (const std::string& part : inputs.scene_parts)
    scene_json["parts"].push_back({{"file", part}, {"sha256", input_sha256(part, kModelPart)}});
  return {{"schema_version", kResultSchemaVersion},
          {"command_line", inputs.command_line},
          {"code_version", code_version()},
          {"simgrid_version", simgrid_version()},
          {"scene", scene_json},
          {"platform", platform_json},
          {"cost_model", {{"file", inputs.cost_model_file},
                          {"sha256", input_sha256(inputs.cost_model_file, kCostModelFile)},
                          {"values", cost_model_values(costs)}}}};
}

}  // namespace ncube

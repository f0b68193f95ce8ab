// Where a result came from (like gem5's config beside its stats): the command line, every
// platform and cost-model value used, the input files with their content hashes, the code's
// and SimGrid's versions. Written into the result file's "provenance" object
// (docs/result-format.md); the sweeps check it before they count a result as done.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "machine/cost_model.h"
#include "machine/platform_config.h"
#include "scene/scene.h"
#include "simulation/simulation.h"

namespace ncube {

struct RunInputs {
  std::vector<std::string> command_line;  // argv as given
  std::string scene_file;
  std::string platform_file;
  std::string cost_model_file;
  // The other files a model file read (its MTL, glTF buffers), each hashed beside the model:
  // the model's own hash alone would not change when its MTL does.
  std::vector<std::string> scene_parts;
};

nlohmann::json provenance_to_json(const RunInputs& inputs, const Scene& scene,
                                  const PlatformConfig& platform, const CostModel& costs,
                                  const SimulationResult& result);

// Every file the run reads, in the order read, each {"role", "file", "sha256"} (role: scene,
// model, model part, platform, cost model), hashed through the input gate with its kind's
// limit: `simulate --list-inputs`, which the sweeps ask instead of parsing models themselves.
nlohmann::json input_listing(const RunInputs& inputs, const PlatformConfig& platform);

nlohmann::json platform_values(const PlatformConfig& platform);
nlohmann::json cost_model_values(const CostModel& costs);

}  // namespace ncube

// The result file (a contract: docs/result-format.md): JSON, the same bytes for the same
// command apart from the host-time fields.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "scene/scene.h"
#include "simulation/simulation.h"

namespace ncube {

// Version of the result file's layout; raised with every change of a field's meaning.
constexpr int kResultSchemaVersion = 2;

nlohmann::json result_to_json(const Scene& scene, const SimulationConfig& config,
                              const SimulationResult& result);

// Writes text to `path` through a temporary file and a rename, so that a reader never sees
// a half-written file. Throws InputError naming the file on failure.
void write_file_atomically(const std::string& path, const std::string& text);

}  // namespace ncube

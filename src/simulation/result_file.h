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

// The counters of the lists (counts/work_counts.h, counts/render_counts.h), each under
// its member's name: the result file's "counts" objects.
// The counters a run of form-factor method `form_factors` and parallelisation
// `parallelisation` writes (writes_counter, parallelisation_writes_counter); of the host work
// counters, those the platform charges (SimulationResult::host_counters_charged).
nlohmann::json counts_to_json(const WorkCounts& counts, const std::string& form_factors = "ray-traced",
                              const std::string& parallelisation = "receivers",
                              const std::vector<std::string>& host_counters_charged = {});
nlohmann::json render_counts_to_json(const RenderCounts& counts);

nlohmann::json result_to_json(const Scene& scene, const SimulationConfig& config,
                              const SimulationResult& result);

}  // namespace ncube

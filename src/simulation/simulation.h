// One simulated run: checks the configuration and the nodes' memory, builds the nCube2
// platform, places the node programs on it, runs SimGrid to the end and collects what the
// result file reports. One per process (SimGrid allows one Engine per process).
#pragma once

#include "machine/cost_model.h"
#include "machine/platform_config.h"
#include "scene/scene.h"
#include "simulation/configuration_check.h"
#include "simulation/memory_check.h"
#include "simulation/simulation_config.h"
#include "simulation/simulation_result.h"

namespace ncube {

// Runs the simulation. Status kFailed when a node program did not reach its end (the
// simulation deadlocked) or a reported number is not finite; then `failure` says which.
SimulationResult run_simulation(const Scene& scene, const SimulationConfig& config,
                                const PlatformConfig& platform, const CostModel& costs);

}  // namespace ncube

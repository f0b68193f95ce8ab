// Checking a run's configuration against the scene and the platform before anything is
// built: bad input is refused with a message naming the option (exit code 2).
#pragma once

#include "machine/platform_config.h"
#include "scene/scene.h"
#include "simulation/simulation_config.h"

namespace ncube {

// Throws InputError for a configuration the simulator cannot run.
void check_configuration(const Scene& scene, const SimulationConfig& config,
                         const PlatformConfig& platform);

}  // namespace ncube

// What a ray-patch test costs the host in each scene of scenes/, the probe's loop timed round
// by round in one process (src/tools/scene_test_cost.cpp; build/machine_probe --scenes).
#pragma once

#include <string>

namespace ncube {

// Prints one line per scene and order of its patches; `platform_file` gives the rates taken
// off (ray_speed, blocked_ray_speed) and the test_speed compared with. Returns 0.
int print_scene_test_costs(int rounds, const std::string& platform_file);

}  // namespace ncube

// The memory check before a run starts: every node's modeled bytes (nodes/memory_plan.h,
// and the rendering phase's when it runs) against the platform's node memory. (Sections 4.1
// and 4.2: the radiosity processors' bytes change as the run goes; they check as they cut.)
#pragma once

#include <vector>

#include "machine/cost_model.h"
#include "machine/platform_config.h"
#include "nodes/memory_plan.h"
#include "scene/scene.h"
#include "simulation/simulation_config.h"
#include "simulation/simulation_result.h"

namespace ncube {

// Every node's modeled bytes in the radiosity run, in node order.
std::vector<NodeMemory> node_memory(const Scene& scene, const SimulationConfig& config,
                                    const CostModel& costs);

// The first node (in node order) whose modeled memory exceeds the platform's node memory;
// node -1 when every node fits. Needs the patches' element counts only, not the elements,
// so it can run before the host allocates them. The rendering phase's records are checked
// when it starts, from the solution (run_render_phase); here only the rest of its peak.
OutOfMemory first_node_out_of_memory(const Scene& scene, const SimulationConfig& config,
                                     const PlatformConfig& platform, const CostModel& costs);

}  // namespace ncube

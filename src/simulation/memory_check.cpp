#include "simulation/memory_check.h"

#include "nodes/placement.h"
#include "simulation/parallelisations.h"
#include "simulation/render_phase.h"

namespace ncube {

std::vector<NodeMemory> node_memory(const Scene& scene, const SimulationConfig& config,
                                    const CostModel& costs) {
  const ProgramSetup setup{scene, Placement{config.radiosity_processors, config.visibility_processors},
                           config, 0.0};
  return parallelisations().at(config.parallelisation).plan_memory(setup, costs);
}

OutOfMemory first_node_out_of_memory(const Scene& scene, const SimulationConfig& config,
                                     const PlatformConfig& platform, const CostModel& costs) {
  for (const NodeMemory& m : node_memory(scene, config, costs))
    if (m.bytes > platform.node_memory) return {m.node, m.role, m.bytes, platform.node_memory};
  if (config.render.enabled) {  // the rendering phase's peak without its records (section 2.3)
    const std::vector<double> render = render_memory_without_records(
        config.render, config.radiosity_processors, config.visibility_processors, costs);
    for (std::size_t node = 0; node < render.size(); ++node)
      if (render[node] > platform.node_memory)
        return {int(node), NodeRole::kRendering, render[node], platform.node_memory};
  }
  return {};
}

}  // namespace ncube

#include "simulation/simulation.h"

#include <chrono>
#include <memory>
#include <numeric>
#include <simgrid/s4u/Actor.hpp>
#include <simgrid/s4u/Engine.hpp>
#include <xbt/log.h>

#include "machine/hypercube.h"
#include "nodes/radiosity_processor.h"
#include "util/input_error.h"

namespace ncube {

void check_configuration(const Scene& scene, const SimulationConfig& config,
                         const PlatformConfig& platform) {
  const int r = config.radiosity_processors, v = config.visibility_processors;
  const std::string rv = "R=" + std::to_string(r) + ", V=" + std::to_string(v);
  if (r < 1) throw InputError("--R " + std::to_string(r) + ": at least one radiosity processor is needed");
  if (v < 0) throw InputError("--V " + std::to_string(v) + ": must be 0 or more");
  if (long(r) * (v + 1) > platform.node_count())
    throw InputError(rv + " needs " + std::to_string(long(r) * (v + 1)) + " nodes; the platform has " +
                     std::to_string(platform.node_count()));
  if (r > int(scene.patches.size()))
    throw InputError(rv + ": more radiosity processors than the scene's " +
                     std::to_string(scene.patches.size()) + " patches");
  if (r != 1 || v != 0)
    throw InputError(rv + ": parallel configurations are not supported yet (only R=1, V=0)");
  if (!is_valid_part_count(config.options.samples))
    throw InputError("--samples " + std::to_string(config.options.samples) +
                     ": must be a perfect square from 1 to 64 (e.g. 16 or 64)");
}

SimulationResult run_simulation(const Scene& scene, const SimulationConfig& config,
                                const PlatformConfig& platform, const CostModel& costs) {
  const auto host_start = std::chrono::steady_clock::now();
  check_configuration(scene, config, platform);

  int argc = 1;
  char program[] = "simulate";
  char* argv[] = {program, nullptr};
  simgrid::s4u::Engine engine(&argc, argv);
  xbt_log_control_set("root.thresh:warning");
  configure_network_model(engine);
  const std::vector<simgrid::s4u::Host*> hosts = build_hypercube(platform);

  // R = 1, V = 0: the sequential program on node 0 (section 2.2 with one processor).
  std::vector<int> all_patches(scene.patches.size());
  std::iota(all_patches.begin(), all_patches.end(), 0);
  RadiosityEngine radiosity(scene, all_patches);
  const Occluders occluders(scene, all_patches, config.options.ray_policy);
  NodeRuntime runtime(0, "radiosity", platform, costs);
  RadiosityProcessor processor(runtime, radiosity, occluders, config.options);
  simgrid::s4u::Actor::create("radiosity-0", hosts[0], [&processor] { processor.run(); });
  engine.run();

  SimulationResult result;
  result.simulated_seconds = simgrid::s4u::Engine::get_clock();
  result.converged = processor.converged();
  for (const IterationRecord& it : processor.iterations()) {
    result.seconds_per_iteration.push_back(it.end - it.start);
    result.shooters.push_back(it.shooter);
  }
  result.iterations = int(processor.iterations().size());
  for (int p = 0; p < int(scene.patches.size()); ++p)
    result.patch_radiosity.push_back(radiosity.patch_radiosity(p));
  for (int e = 0; e < int(scene.elements.size()); ++e)
    result.element_radiosity.push_back(radiosity.element_radiosity(e));
  result.nodes.push_back(runtime.stats());
  for (const NodeStats& node : result.nodes) result.counts += node.counts;
  result.host_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - host_start).count();
  return result;
}

}  // namespace ncube

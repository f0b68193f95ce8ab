#include "simulation/simulation.h"

#include <chrono>
#include <deque>
#include <memory>
#include <numeric>
#include <simgrid/s4u/Actor.hpp>
#include <simgrid/s4u/Engine.hpp>
#include <xbt/log.h>

#include "machine/hypercube.h"
#include "machine/simgrid_platform_file.h"
#include "machine/simgrid_session.h"
#include "nodes/memory_plan.h"
#include "nodes/radiosity_processor.h"
#include "nodes/visibility_processor.h"
#include "util/input_error.h"

namespace ncube {

void check_configuration(const Scene& scene, const SimulationConfig& config,
                         const PlatformConfig& platform) {
  const int r = config.radiosity_processors, v = config.visibility_processors;
  const std::string rv = "R=" + std::to_string(r) + ", V=" + std::to_string(v);
  if (r < 1) throw InputError("--R " + std::to_string(r) + ": at least one radiosity processor is needed");
  if (v < 0) throw InputError("--V " + std::to_string(v) + ": must be 0 or more");
  if (long(r) * (v + 1) > platform.node_count())
    throw InputError(rv + " needs R x (V + 1) = " + std::to_string(long(r) * (v + 1)) +
                     " nodes; the platform has " + std::to_string(platform.node_count()));
  if (r > int(scene.patches.size()))
    throw InputError(rv + ": more radiosity processors than the scene's " +
                     std::to_string(scene.patches.size()) + " patches");
  if (!is_valid_part_count(config.options.samples))
    throw InputError("--samples " + std::to_string(config.options.samples) +
                     ": must be a perfect square from 1 to 64 (e.g. 16 or 64)");
  if (config.block_size < 1)
    throw InputError("--block-size " + std::to_string(config.block_size) + ": must be at least 1");
}

namespace {

// Everything the node programs of one run are made of; lives until the run is over.
struct Programs {
  std::deque<NodeRuntime> runtimes;
  std::deque<RadiosityEngine> engines;
  std::deque<Occluders> occluders;
  std::deque<RadiosityProcessor> radiosity;
  std::deque<VisibilityProcessor> visibility;
};

void collect_solution(const Scene& scene, const Programs& programs, SimulationResult& result) {
  // Every element and patch is owned by exactly one radiosity processor.
  result.element_radiosity.assign(scene.elements.size(), Rgb(0.0));
  result.patch_radiosity.assign(scene.patches.size(), Rgb(0.0));
  for (const RadiosityEngine& engine : programs.engines) {
    for (int e : engine.owned_elements()) result.element_radiosity[e] = engine.element_radiosity(e);
    for (int p : engine.owned_patches()) result.patch_radiosity[p] = engine.patch_radiosity(p);
  }
}

}  // namespace

SimulationResult run_simulation(const Scene& scene, const SimulationConfig& config,
                                const PlatformConfig& platform, const CostModel& costs) {
  const auto host_start = std::chrono::steady_clock::now();
  check_configuration(scene, config, platform);
  SimulationResult result;
  const int R = config.radiosity_processors, V = config.visibility_processors;
  const ProgramSetup setup{scene,           Placement{R, V},     config.options,
                           scene.emitted_power(), config.block_size, config.pipelined};
  const std::vector<std::vector<int>> owned = partition_patches_by_elements(scene, R);

  // Memory: every node's modeled bytes against its capacity, before anything runs.
  const std::vector<NodeMemory> memory = plan_memory(setup, owned, costs);
  for (const NodeMemory& m : memory)
    if (config.memory_cap && m.bytes > platform.node_memory && result.status == "ok") {
      result.status = "out_of_memory";
      result.out_of_memory = {m.node, m.role, m.bytes, platform.node_memory};
    }

  Programs programs;
  std::vector<int> all_patches(scene.patches.size());
  std::iota(all_patches.begin(), all_patches.end(), 0);
  std::vector<TraceEvent>* trace = config.record_trace ? &result.trace : nullptr;
  for (const NodeMemory& m : memory) {
    programs.runtimes.emplace_back(m.node, m.role, m.rank, platform, costs, trace);
    programs.runtimes.back().set_memory(m.bytes);
  }
  if (result.status == "ok") {  // a node out of memory stops the run before it starts
    simgrid::s4u::Engine& engine = simgrid_engine(config.simgrid_arguments);
    std::vector<simgrid::s4u::Host*> hosts;
    if (platform.format == "simgrid-xml") {
      hosts = simgrid_platform_nodes(platform);  // loaded with its <config> by the reader
    } else {
      apply_simgrid_defaults(platform.simgrid_config);  // before the first zone
      hosts = build_hypercube(platform);
    }
    result.simgrid_config = simgrid_settings_used(config.simgrid_arguments);
    // The occluder sets are read-only and the same for every group: built once, shared.
    if (V == 0) programs.occluders.emplace_back(scene, all_patches, config.options.ray_policy);
    for (int j = 0; j < V; ++j)
      programs.occluders.emplace_back(scene, visibility_share(scene, V, j), config.options.ray_policy);
    const Occluders* all = V == 0 ? &programs.occluders.front() : nullptr;
    int next_runtime = 0;
    for (int rank = 0; rank < R; ++rank) {
      NodeRuntime& rp_runtime = programs.runtimes[next_runtime++];
      RadiosityEngine& radiosity = programs.engines.emplace_back(scene, owned[rank]);
      RadiosityProcessor& rp =
          programs.radiosity.emplace_back(setup, rank, rp_runtime, radiosity, all);
      simgrid::s4u::Actor::create("radiosity-" + std::to_string(rank),
                                  hosts[setup.placement.radiosity_node(rank)], [&rp] { rp.run(); });
      for (int j = 0; j < V; ++j) {
        const Occluders& share = programs.occluders[std::size_t(j)];
        VisibilityProcessor& vp =
            programs.visibility.emplace_back(setup, programs.runtimes[next_runtime++], share);
        simgrid::s4u::Actor::create(
            "visibility-" + std::to_string(rank) + "." + std::to_string(j),
            hosts[setup.placement.visibility_node(rank, j)], [&vp] { vp.run(); });
      }
    }
    if (config.on_iteration) {
      const RadiosityProcessor& master = programs.radiosity.front();
      const double threshold = setup.emitted_power * config.options.convergence_fraction;
      std::size_t reported = 0;
      simgrid::s4u::Engine::on_time_advance_cb([&master, &config, threshold, &reported](double) {
        if (master.iteration_ends().size() == reported) return;
        reported = master.iteration_ends().size();
        config.on_iteration({int(reported), master.largest_unshot_power(), threshold,
                             simgrid::s4u::Engine::get_clock()});
      });
    }
    engine.run();
    const RadiosityProcessor& master = programs.radiosity.front();
    result.simulated_seconds = simgrid::s4u::Engine::get_clock();
    result.converged = master.converged();
    result.shooters = master.shooters();
    result.iterations = int(master.shooters().size());
    double previous = 0.0;
    for (double end : master.iteration_ends()) {
      result.iteration_seconds.push_back(end - previous);
      previous = end;
    }
    collect_solution(scene, programs, result);
  }
  for (const NodeRuntime& runtime : programs.runtimes) {
    result.nodes.push_back(runtime.stats());
    result.counts += runtime.stats().counts;
  }
  result.host_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - host_start).count();
  return result;
}

}  // namespace ncube

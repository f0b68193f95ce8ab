#include "simulation/simulation.h"

#include <chrono>
#include <cmath>
#include <stdexcept>
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
  // In 64 bits: R and V are up to 2^31 - 1 each.
  if (long(r) * (long(v) + 1) > platform.node_count())
    throw InputError(rv + " needs R x (V + 1) = " + std::to_string(long(r) * (long(v) + 1)) +
                     " nodes; the platform has " + std::to_string(platform.node_count()));
  if (r > int(scene.patches.size()))
    throw InputError(rv + ": more radiosity processors than the scene's " +
                     std::to_string(scene.patches.size()) + " patches");
  if (!is_valid_part_count(config.options.samples))
    throw InputError("--samples " + std::to_string(config.options.samples) +
                     ": must be a perfect square from 1 to 64 (e.g. 16 or 64)");
  if (config.block_size < 1)
    throw InputError("--block-size " + std::to_string(config.block_size) + ": must be at least 1");
  check_render_configuration(config.render, config.node_count());
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

std::vector<NodeMemory> memory_plan(const Scene& scene, const SimulationConfig& config,
                                    const CostModel& costs) {
  const ProgramSetup setup{scene, Placement{config.radiosity_processors, config.visibility_processors},
                           config.options, 0.0, config.block_size, config.pipelined};
  return plan_memory(setup, partition_patches_by_elements(scene, config.radiosity_processors), costs);
}

// Why a finished run cannot be reported as ok ("" if it can): a node program that did not
// reach its end, or a number that is not finite.
std::string failure_of(const SimulationResult& result, const std::deque<NodeRuntime>& runtimes) {
  for (const NodeRuntime& runtime : runtimes)
    if (!runtime.finished())
      return "node " + std::to_string(runtime.stats().node) + " (" + runtime.stats().role +
             " processor) did not finish: the simulation stopped at " +
             std::to_string(result.simulated_seconds) + " simulated seconds with it blocked";
  const auto finite = [](double x) { return std::isfinite(x); };
  if (!finite(result.simulated_seconds)) return "the simulated time is not finite";
  for (double s : result.iteration_seconds)
    if (!finite(s)) return "an iteration's simulated time is not finite";
  for (const Rgb& b : result.patch_radiosity)
    if (!finite(b.r) || !finite(b.g) || !finite(b.b)) return "a patch radiosity is not finite";
  for (const NodeStats& n : result.nodes)
    if (!finite(n.compute_seconds) || !finite(n.overhead_seconds) || !finite(n.waiting_seconds) ||
        !finite(n.bytes_sent) || !finite(n.peak_memory_bytes))
      return "a statistic of node " + std::to_string(n.node) + " is not finite";
  return "";
}

void collect_solution(const Scene& scene, const Programs& programs, SimulationResult& result) {
  // Every patch is held by exactly one radiosity processor (section 4).
  result.solution.assign(scene.patches.size(), PatchSolution{});
  result.patch_radiosity.assign(scene.patches.size(), Rgb(0.0));
  for (const RadiosityEngine& engine : programs.engines) {
    result.held_patches.push_back(engine.store().patch_indices());
    for (PatchSolution& p : engine.store().solution()) {
      result.patch_radiosity[std::size_t(p.patch)] = engine.patch_radiosity(p.patch);
      result.solution[std::size_t(p.patch)] = std::move(p);
    }
  }
  // The level-0 view: a cut element shows the area-weighted mean of its descendants.
  result.element_radiosity.assign(std::size_t(scene.element_total()), Rgb(0.0));
  std::vector<double> area(result.element_radiosity.size(), 0.0);
  for (const PatchSolution& p : result.solution) {
    const Patch& patch = scene.patches[std::size_t(p.patch)];
    for (std::size_t k = 0; k < p.cells.size(); ++k) {
      const ElementCell& c = p.cells[k];
      const std::size_t e = std::size_t(patch.first_element) +
                            std::size_t(c.j >> c.level) * std::size_t(patch.nu) + std::size_t(c.i >> c.level);
      const double a = c.level == 0 ? 1.0 : cell_polygon(patch, c).area();
      result.element_radiosity[e] += p.radiosity[k] * a;
      area[e] += a;
    }
  }
  for (std::size_t e = 0; e < area.size(); ++e) result.element_radiosity[e] /= area[e];
}

}  // namespace

OutOfMemory first_node_out_of_memory(const Scene& scene, const SimulationConfig& config,
                                     const PlatformConfig& platform, const CostModel& costs) {
  for (const NodeMemory& m : memory_plan(scene, config, costs))
    if (m.bytes > platform.node_memory) return {m.node, m.role, m.bytes, platform.node_memory};
  if (config.render.enabled) {  // the rendering phase's peak without its records (section 2.3)
    const std::vector<double> render = render_memory_without_records(
        config.render, config.radiosity_processors, config.visibility_processors, costs);
    for (std::size_t node = 0; node < render.size(); ++node)
      if (render[node] > platform.node_memory)
        return {int(node), "rendering", render[node], platform.node_memory};
  }
  return {};
}

SimulationResult run_simulation(const Scene& scene, const SimulationConfig& config,
                                const PlatformConfig& platform, const CostModel& costs) {
  const auto host_start = std::chrono::steady_clock::now();
  check_configuration(scene, config, platform);
  SimulationResult result;
  const int R = config.radiosity_processors, V = config.visibility_processors;
  const ProgramSetup setup{scene,           Placement{R, V},     config.options,
                           scene.emitted_power(), config.block_size, config.pipelined,
                           config.memory_cap,     config.balancing};
  const std::vector<std::vector<int>> owned = partition_patches_by_elements(scene, R);

  // Memory: every node's modeled bytes against its capacity, before anything runs.
  const std::vector<NodeMemory> memory = plan_memory(setup, owned, costs);
  if (config.memory_cap) {
    result.out_of_memory = first_node_out_of_memory(scene, config, platform, costs);
    if (result.out_of_memory.node >= 0) result.status = "out_of_memory";
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
    if (V == 0) programs.occluders.emplace_back(scene, all_patches, config.options.ray_policy,
                                                config.options.visibility);
    for (int j = 0; j < V; ++j)
      programs.occluders.emplace_back(scene, visibility_share(scene, V, j), config.options.ray_policy,
                                     config.options.visibility);
    const Occluders* all = V == 0 ? &programs.occluders.front() : nullptr;
    int next_runtime = 0;
    for (int rank = 0; rank < R; ++rank) {
      NodeRuntime& rp_runtime = programs.runtimes[next_runtime++];
      RadiosityEngine& radiosity = programs.engines.emplace_back(scene, owned[std::size_t(rank)]);
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
    result.elements_per_iteration = master.elements_per_iteration();
    for (const RadiosityProcessor& rp : programs.radiosity) result.patches_moved += rp.patches_sent();
    if (master.out_of_memory().node >= 0) {  // a processor could not make its cuts (4.1, 4.2)
      result.status = "out_of_memory";
      const NodeStats& node = programs.runtimes[std::size_t(master.out_of_memory().node)].stats();
      result.out_of_memory = {node.node, node.role, master.out_of_memory().needed_bytes,
                              platform.node_memory};
    }
    if (config.render.enabled && result.status == "ok" && failure_of(result, programs.runtimes).empty()) {
      result.render = run_render_phase(scene, config.render, R, V, result.solution, hosts, platform,
                                       costs, config.memory_cap, trace, &result.held_patches);
      if (result.render.out_of_memory_node >= 0) {  // its records do not fit (section 2.3)
        result.status = "out_of_memory";
        result.out_of_memory = {result.render.out_of_memory_node, "rendering",
                                result.render.out_of_memory_bytes, platform.node_memory};
      }
    }
  }
  for (const NodeRuntime& runtime : programs.runtimes) {
    result.nodes.push_back(runtime.stats());
    result.counts += runtime.stats().counts;
  }
  if (result.status == "ok") {
    result.failure = failure_of(result, programs.runtimes);
    if (result.failure.empty()) result.failure = result.render.failure;
    if (!result.failure.empty()) result.status = "failed";
  }
  result.host_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - host_start).count();
  return result;
}

}  // namespace ncube

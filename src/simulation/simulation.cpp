#include "simulation/simulation.h"

#include <chrono>
#include <cmath>

#include <simgrid/s4u/Engine.hpp>

#include "machine/simgrid_session.h"
#include "nodes/placement.h"
#include "simulation/node_programs.h"
#include "simulation/parallelisations.h"
#include "machine/work_kinds.h"
#include "simulation/simulated_platform.h"

namespace ncube {

const char* status_name(RunStatus status) {
  switch (status) {
    case RunStatus::kOk: return "ok";
    case RunStatus::kOutOfMemory: return "out_of_memory";
    case RunStatus::kFailed: return "failed";
  }
  return "?";
}

namespace {

// Why a finished run cannot be reported as ok ("" if it can): a node program that did not
// reach its end, or a number that is not finite.
std::string failure_of(const SimulationResult& result, const NodePrograms& programs) {
  const std::string unfinished = unfinished_node(programs, result.simulated_seconds);
  if (!unfinished.empty()) return unfinished;
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

// Runs the node programs to the end on the simulated machine, then the rendering phase if
// it is enabled and the radiosity run finished.
void run_programs(const Scene& scene, const SimulationConfig& config,
                  const PlatformConfig& platform, const CostModel& costs,
                  const ProgramSetup& setup, NodePrograms& programs, SimulationResult& result) {
  const Parallelisation& parallelisation = parallelisations().at(setup.parallelisation);
  const std::vector<simgrid::s4u::Host*> hosts =
      build_simulated_platform(platform, config.simgrid_arguments);
  result.simgrid_config = simgrid_settings_used(config.simgrid_arguments);
  parallelisation.launch(programs, setup, config, hosts);
  simgrid::s4u::Engine::get_instance()->run();
  programs.exceptions.rethrow_first();  // before anything is written
  result.simulated_seconds = simgrid::s4u::Engine::get_clock();
  result.activities = std::move(programs.activities);
  parallelisation.collect(scene, programs, platform, result);
  result.element_radiosity = level_zero_radiosity(scene, result.solution);
  if (config.render.enabled && result.status == RunStatus::kOk && failure_of(result, programs).empty()) {
    result.render = run_render_phase(scene, config.render, setup.placement.radiosity_processors,
                                     setup.placement.visibility_processors, result.solution, hosts,
                                     platform, costs, config.memory_cap,
                                     config.record_trace ? &result.trace : nullptr,
                                     &result.held_patches);
    if (result.render.out_of_memory_node >= 0) {  // its records do not fit (section 2.3)
      result.status = RunStatus::kOutOfMemory;
      result.out_of_memory = {result.render.out_of_memory_node, NodeRole::kRendering,
                              result.render.out_of_memory_bytes, platform.node_memory};
    }
  }
}

}  // namespace

SimulationResult run_simulation(const Scene& scene, const SimulationConfig& config,
                                const PlatformConfig& platform, const CostModel& costs) {
  const auto host_start = std::chrono::steady_clock::now();
  check_configuration(scene, config, platform);
  SimulationResult result;
  const int R = config.radiosity_processors, V = config.visibility_processors;
  const ProgramSetup setup{scene, Placement{R, V}, config, scene.emitted_power()};

  // Memory: every node's modeled bytes against its capacity, before anything runs.
  if (config.memory_cap) {
    result.out_of_memory = first_node_out_of_memory(scene, config, platform, costs);
    if (result.out_of_memory.node >= 0) result.status = RunStatus::kOutOfMemory;
  }

  NodePrograms programs;
  create_runtimes(programs, parallelisations().at(setup.parallelisation).plan_memory(setup, costs),
                  platform, costs, config.record_trace ? &result.trace : nullptr);
  if (result.status == RunStatus::kOk)  // a node out of memory stops the run before it starts
    run_programs(scene, config, platform, costs, setup, programs, result);

  for (const NodeRuntime& runtime : programs.runtimes) {
    result.nodes.push_back(runtime.stats());
    result.counts += runtime.stats().counts;
  }
#define NCUBE_HOST_CHARGED(member, cost, doc) \
  if (charges_counter(platform, #member)) result.host_counters_charged.push_back(#member);
  NCUBE_HOST_WORK_COUNTERS(NCUBE_HOST_CHARGED)
#undef NCUBE_HOST_CHARGED
  if (result.status == RunStatus::kOk) {
    result.failure = failure_of(result, programs);
    if (result.failure.empty()) result.failure = result.render.failure;
    if (!result.failure.empty()) result.status = RunStatus::kFailed;
  }
  result.host_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - host_start).count();
  return result;
}

}  // namespace ncube

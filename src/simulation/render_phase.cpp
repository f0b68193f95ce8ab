#include "simulation/render_phase.h"

#include <algorithm>
#include <deque>
#include <simgrid/s4u/Actor.hpp>
#include <simgrid/s4u/Engine.hpp>

#include "nodes/placement.h"
#include "nodes/render_processor.h"
#include "simulation/actor_exceptions.h"
#include "simulation/actor_stacks.h"
#include "util/input_error.h"

namespace ncube {

void check_render_configuration(const RenderOptions& options, int nodes) {
  if (options.enabled && options.distribution == RenderDistribution::kHypercube &&
      !is_power_of_two(nodes))
    throw InputError("--render-distribution hypercube: the run's " + std::to_string(nodes) +
                     " nodes are not a power of two (a hypercube); use --render-distribution ring");
}

std::vector<double> render_memory(const Scene& scene, const RenderOptions& options, int R, int V,
                                  const std::vector<PatchSolution>& solution,
                                  const CostModel& costs) {
  const std::vector<std::vector<int>> owned = partition_patches_by_elements(scene, R);
  return plan_render_memory(options, R * (V + 1),
                            share_bytes(starting_shares(scene, solution, owned, V), costs), costs);
}

std::vector<double> render_memory_without_records(const RenderOptions& options, int R, int V,
                                                  const CostModel& costs) {
  const int N = R * (V + 1);
  return plan_render_memory(options, N, std::vector<double>(std::size_t(N), 0.0), costs);
}

RenderResult run_render_phase(const Scene& scene, const RenderOptions& options, int R, int V,
                              const std::vector<PatchSolution>& solution,
                              const std::vector<simgrid::s4u::Host*>& hosts,
                              const PlatformConfig& platform, const CostModel& costs,
                              bool memory_cap, std::vector<TraceEvent>* trace,
                              const std::vector<std::vector<int>>* held_patches) {
  const int N = R * (V + 1);
  const std::vector<std::vector<int>> owned =
      held_patches ? *held_patches : partition_patches_by_elements(scene, R);
  const RenderSetup setup{scene, options, N, starting_shares(scene, solution, owned, V)};
  // Memory, from the records the solution has now (subdivision changes them as it runs).
  const std::vector<double> memory =
      plan_render_memory(options, N, share_bytes(setup.shares, costs), costs);
  RenderResult result;
  if (memory_cap)
    for (int node = 0; node < N; ++node)
      if (memory[std::size_t(node)] > platform.node_memory) {
        result.out_of_memory_node = node;
        result.out_of_memory_bytes = memory[std::size_t(node)];
        return result;
      }
  std::deque<NodeRuntime> runtimes;
  std::deque<RenderProcessor> programs;
  reserve_actor_stacks(std::size_t(N));
  ActorExceptions exceptions;  // a program's exception (the host out of memory), rethrown
  for (int node = 0; node < N; ++node) {
    const bool radiosity = node % (V + 1) == 0;
    NodeRuntime& runtime = runtimes.emplace_back(node, radiosity ? NodeRole::kRadiosity : NodeRole::kVisibility,
                                                 node / (V + 1), platform, costs, trace);
    runtime.set_memory(memory[std::size_t(node)]);
    runtime.set_trace_render();
    RenderProcessor& program = programs.emplace_back(setup, node, runtime);
    create_actor("render-" + std::to_string(node), hosts[std::size_t(node)],
                 exceptions.guard([&program] { program.run(); }));
  }
  result.ran = true;
  const double start = simgrid::s4u::Engine::get_clock();
  simgrid::s4u::Engine::get_instance()->run();
  exceptions.rethrow_first();
  result.simulated_seconds = simgrid::s4u::Engine::get_clock() - start;
  double sum = 0.0, max = 0.0;
  for (int node = 0; node < N; ++node) {
    const NodeRuntime& runtime = runtimes[std::size_t(node)];
    const RenderProcessor& program = programs[std::size_t(node)];
    if (!runtime.finished() && result.failure.empty())
      result.failure = "node " + std::to_string(node) +
                       " did not finish the rendering phase: the simulation stopped with it blocked";
    result.nodes.push_back({runtime.stats(), program.rows(), program.rasterise_seconds(),
                            runtime.render_counts()});
    sum += program.rasterise_seconds();
    max = std::max(max, program.rasterise_seconds());
  }
  result.imbalance = sum > 0.0 ? max / (sum / N) : 1.0;
  if (result.failure.empty()) result.picture = programs.front().picture();
  return result;
}

}  // namespace ncube

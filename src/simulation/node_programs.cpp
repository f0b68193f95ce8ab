#include "simulation/node_programs.h"

#include <memory>
#include <numeric>
#include <utility>

#include <simgrid/s4u/Actor.hpp>
#include <simgrid/s4u/Engine.hpp>

#include "simulation/actor_stacks.h"

namespace ncube {

void create_runtimes(NodePrograms& programs, const std::vector<NodeMemory>& memory,
                     const PlatformConfig& platform, const CostModel& costs,
                     std::vector<TraceEvent>* trace) {
  if (!ActivityRecord::requested_path().empty())
    programs.activities = std::make_unique<ActivityRecord>();
  for (const NodeMemory& m : memory) {
    programs.runtimes.emplace_back(m.node, m.role, m.rank, platform, costs, trace);
    programs.runtimes.back().set_memory(m.bytes);
    if (programs.activities)
      programs.runtimes.back().record_activities(&programs.activities->add_node(m.node));
  }
}

void launch_node_programs(NodePrograms& programs, const ProgramSetup& setup,
                          const std::vector<std::vector<int>>& owned,
                          const std::vector<simgrid::s4u::Host*>& hosts) {
  const Scene& scene = setup.scene;
  const int R = setup.placement.radiosity_processors, V = setup.placement.visibility_processors;
  // The sets are read-only and the same for every group: built once and shared.
  std::vector<std::vector<int>> patch_sets;
  if (V == 0) {
    patch_sets.emplace_back(scene.patches.size());
    std::iota(patch_sets.back().begin(), patch_sets.back().end(), 0);
  }
  for (int j = 0; j < V; ++j) patch_sets.push_back(visibility_share(scene, V, j));
  build_host_machinery(programs.host, scene, patch_sets, setup.options, V, R, setup.block_size,
                       setup.loads_change());
  const OccluderSet* all = V == 0 ? programs.host.occluders.front().get() : nullptr;
  reserve_actor_stacks(std::size_t(R) * std::size_t(V + 1));
  int next_runtime = 0;
  for (int rank = 0; rank < R; ++rank) {
    NodeRuntime& rp_runtime = programs.runtimes[next_runtime++];
    RadiosityEngine& radiosity = programs.engines.emplace_back(scene, owned[std::size_t(rank)]);
    radiosity.use_host_assist(programs.host.assist.get(), rank);
    RadiosityProcessor& rp = programs.radiosity.emplace_back(setup, rank, rp_runtime, radiosity, all);
    create_actor("radiosity-" + std::to_string(rank), hosts[setup.placement.radiosity_node(rank)],
                 programs.exceptions.guard([&rp] { rp.run(); }));
    for (int j = 0; j < V; ++j) {
      const OccluderSet& share = *programs.host.occluders[std::size_t(j)];
      VisibilityProcessor& vp =
          programs.visibility.emplace_back(setup, programs.runtimes[next_runtime++], share);
      create_actor(
          "visibility-" + std::to_string(rank) + "." + std::to_string(j),
          hosts[setup.placement.visibility_node(rank, j)],
          programs.exceptions.guard([&vp] { vp.run(); }));
    }
  }
}

void collect_solution(const Scene& scene, const NodePrograms& programs,
                      std::vector<PatchSolution>& solution, std::vector<Rgb>& patch_radiosity,
                      std::vector<std::vector<int>>& held_patches) {
  // Every patch is held by exactly one radiosity processor (section 4).
  solution.assign(scene.patches.size(), PatchSolution{});
  patch_radiosity.assign(scene.patches.size(), Rgb(0.0));
  held_patches.clear();
  for (const RadiosityEngine& engine : programs.engines) {
    held_patches.push_back(engine.store().patch_indices());
    for (PatchSolution& p : engine.store().solution()) {
      patch_radiosity[std::size_t(p.patch)] = engine.patch_radiosity(p.patch);
      solution[std::size_t(p.patch)] = std::move(p);
    }
  }
}

std::vector<Rgb> level_zero_radiosity(const Scene& scene, const std::vector<PatchSolution>& solution) {
  std::vector<Rgb> radiosity(std::size_t(scene.element_total()), Rgb(0.0));
  std::vector<double> area(radiosity.size(), 0.0);
  for (const PatchSolution& p : solution) {
    const Patch& patch = scene.patches[std::size_t(p.patch)];
    for (std::size_t k = 0; k < p.cells.size(); ++k) {
      const ElementCell& c = p.cells[k];
      const std::size_t e = std::size_t(patch.first_element) +
                            std::size_t(c.j >> c.level) * std::size_t(patch.nu) + std::size_t(c.i >> c.level);
      const double a = c.level == 0 ? 1.0 : cell_polygon(patch, c).area();
      radiosity[e] += p.radiosity[k] * a;
      area[e] += a;
    }
  }
  for (std::size_t e = 0; e < area.size(); ++e) radiosity[e] /= area[e];
  return radiosity;
}

std::string unfinished_node(const NodePrograms& programs, double simulated_seconds) {
  for (const NodeRuntime& runtime : programs.runtimes)
    if (!runtime.finished())
      return "node " + std::to_string(runtime.stats().node) + " (" +
             role_name(runtime.stats().role) +
             " processor) did not finish: the simulation stopped at " +
             std::to_string(simulated_seconds) + " simulated seconds with it blocked";
  return "";
}

}  // namespace ncube

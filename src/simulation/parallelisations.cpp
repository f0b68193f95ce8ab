#include "simulation/parallelisations.h"

#include <algorithm>
#include <deque>
#include <numeric>
#include <string>
#include <vector>

#include <simgrid/s4u/Actor.hpp>

#include "nodes/placement.h"
#include "simulation/actor_stacks.h"
#include "util/input_error.h"

namespace ncube {

namespace {

// The paper's program (sections 2.2, 3, 4): patches partitioned by elements over R
// radiosity processors, each with V visibility processors.
std::vector<std::vector<int>> owned_patches(const ProgramSetup& setup) {
  return partition_patches_by_elements(setup.scene, setup.placement.radiosity_processors);
}

void check_receivers(const Scene&, const SimulationConfig& config) {
  if (config.shooters_per_iteration != 0)
    throw InputError("--shooters-per-iteration " + std::to_string(config.shooters_per_iteration) +
                     ": applies to --parallelisation shooters only (the paper's program shoots "
                     "one patch per iteration)");
}

void launch_receivers(NodePrograms& programs, const ProgramSetup& setup,
                      const SimulationConfig& config, const std::vector<simgrid::s4u::Host*>& hosts) {
  launch_node_programs(programs, setup, owned_patches(setup), hosts);
  report_iterations(programs.radiosity.front(), config, setup.emitted_power);
}

void collect_receivers(const Scene& scene, const NodePrograms& programs,
                       const PlatformConfig& platform, SimulationResult& result) {
  const RadiosityProcessor& master = programs.radiosity.front();
  result.converged = master.converged();
  result.shooters = master.shooters();
  result.iterations = int(master.shooters().size());
  double previous = 0.0;
  for (double end : master.iteration_ends()) {
    result.iteration_seconds.push_back(end - previous);
    previous = end;
  }
  // Sections 4.1, 4.2: every radiosity processor's elements at the start of each iteration.
  result.elements_per_iteration = master.elements_per_iteration();
  collect_solution(scene, programs, result.solution, result.patch_radiosity, result.held_patches);
  for (const RadiosityProcessor& rp : programs.radiosity) {
    result.patches_moved += rp.patches_sent();
    result.transfer_messages += rp.transfers_sent();
    result.transfer_bytes += rp.transfer_bytes_sent();
  }
  if (master.out_of_memory().node >= 0) {  // a processor could not make its cuts (4.1, 4.2)
    result.status = RunStatus::kOutOfMemory;
    const NodeStats& node = programs.runtimes[std::size_t(master.out_of_memory().node)].stats();
    result.out_of_memory = {node.node, node.role, master.out_of_memory().needed_bytes,
                            platform.node_memory};
  }
}

// What a shooter-centred scheme reports from its node 0: convergence, the shots, and the
// iterations' simulated seconds (each iteration's end less the previous one's).
template <typename ShooterCentredNode>
void take_iterations(const ShooterCentredNode& first, SimulationResult& result) {
  result.converged = first.converged();
  result.shooters = first.shooters();
  result.iterations = int(first.iteration_ends().size());
  double previous = 0.0;
  for (double end : first.iteration_ends()) {
    result.iteration_seconds.push_back(end - previous);
    previous = end;
  }
}

// What a shooter-centred scheme refuses, each option with the scheme's own reason (the words
// after "--parallelisation NAME: "); the same four rules for every such scheme.
struct ShooterCentredReasons {
  std::string visibility, subdivide, balance;
};

void check_shooter_centred(const SimulationConfig& config, const std::string& scheme,
                           const ShooterCentredReasons& why) {
  const std::string what = "--parallelisation " + scheme + ": ";
  if (config.visibility_processors != 0)
    throw InputError(what + "V=" + std::to_string(config.visibility_processors) + ", but " +
                     why.visibility + " (use --V 0)");
  if (config.options.subdivision.enabled)
    throw InputError(what + "--subdivide is not modelled (" + why.subdivide + ")");
  if (config.balancing.enabled)
    throw InputError(what + "--balance does not apply (" + why.balance + ")");
  if (config.render.enabled)
    throw InputError(what + "--render-parallel is not modelled for this scheme");
  if (config.shooters_per_iteration > config.radiosity_processors)
    throw InputError("--shooters-per-iteration " + std::to_string(config.shooters_per_iteration) +
                     ": at most one shooter per node, and R=" +
                     std::to_string(config.radiosity_processors));
}

// The shooter-centred scheme (nodes/shooter_processor.h): R nodes, each the whole scene.
void check_shooters(const Scene&, const SimulationConfig& config) {
  check_shooter_centred(config, "shooters",
                        {"every node of the shooter-centred scheme holds the whole scene and "
                         "traces its own rays",
                         "every node would have to cut the same elements",
                         "every node holds every patch"});
}

// Launches the R nodes of a shooter-centred scheme, each holding the whole scene (an engine
// over every patch) and sharing the host's fast occluders over it, read-only, as the paper's
// program without visibility processors has them. `make(rank, engine, occluders)` builds
// rank's node program into `nodes` (a deque of programs, in rank order) and returns it.
template <class Node, class Make>
void launch_whole_scene_nodes(NodePrograms& programs, const ProgramSetup& setup,
                              const SimulationConfig& config,
                              const std::vector<simgrid::s4u::Host*>& hosts,
                              std::deque<Node>& nodes, const std::string& actor_name, Make make) {
  const Scene& scene = setup.scene;
  const int R = setup.placement.radiosity_processors;
  std::vector<int> all(scene.patches.size());
  std::iota(all.begin(), all.end(), 0);
  build_host_machinery(programs.host, scene, {all}, setup.options, 0, R, setup.block_size, false);
  const OccluderSet& occluders = *programs.host.occluders.front();
  reserve_actor_stacks(std::size_t(R));
  for (int rank = 0; rank < R; ++rank) {
    RadiosityEngine& engine = programs.engines.emplace_back(scene, all);
    engine.use_host_assist(programs.host.assist.get(), rank);
    Node& node = make(rank, engine, occluders);
    create_actor(actor_name + "-" + std::to_string(rank), hosts[setup.placement.radiosity_node(rank)],
                 programs.exceptions.guard([&node] { node.run(); }));
  }
  report_iterations(nodes.front(), config, setup.emitted_power);
}

void launch_shooters(NodePrograms& programs, const ProgramSetup& setup,
                     const SimulationConfig& config, const std::vector<simgrid::s4u::Host*>& hosts) {
  launch_whole_scene_nodes(
      programs, setup, config, hosts, programs.shooters, "shooter",
      [&](int rank, RadiosityEngine& engine, const OccluderSet& occluders) -> ShooterProcessor& {
        return programs.shooters.emplace_back(setup, rank, programs.runtimes[std::size_t(rank)],
                                              engine, occluders);
      });
}

void collect_shooters(const Scene& scene, const NodePrograms& programs, const PlatformConfig&,
                      SimulationResult& result) {
  const ShooterProcessor& first = programs.shooters.front();
  take_iterations(first, result);
  // Every node holds the same solution; node 0's is reported. A node whose radiosities
  // differ would be a bug of the exchange: the run fails (exit 4) naming it.
  const RadiosityEngine& reported = programs.engines.front();
  result.solution = reported.store().solution();
  result.patch_radiosity.assign(scene.patches.size(), Rgb(0.0));
  for (const PatchSolution& p : result.solution)
    result.patch_radiosity[std::size_t(p.patch)] = reported.patch_radiosity(p.patch);
  for (const RadiosityEngine& engine : programs.engines) {
    result.held_patches.push_back(engine.store().patch_indices());
    const std::vector<PatchSolution> solution = engine.store().solution();
    for (std::size_t p = 0; p < solution.size() && result.status == RunStatus::kOk; ++p)
      if (solution[p].radiosity != result.solution[p].radiosity) {
        result.status = RunStatus::kFailed;
        result.failure = "node " + std::to_string(result.held_patches.size() - 1) +
                         " ends with radiosities that differ from node 0's";
      }
  }
}

// Çapın, Aykanat & Özgüç's scheme (nodes/circulation_processor.h): R nodes on a ring, each
// owning the paper's share of the patches.
void check_circulation(const Scene&, const SimulationConfig& config) {
  check_shooter_centred(config, "circulation",
                        {"every node of the circulation scheme computes its shooter's form "
                         "factors to the whole scene itself",
                         "the blocks of the light distribution would change size",
                         "the source's task assignment is static"});
}

void launch_circulation(NodePrograms& programs, const ProgramSetup& setup,
                        const SimulationConfig& config, const std::vector<simgrid::s4u::Host*>& hosts) {
  const std::vector<std::vector<int>> owned = owned_patches(setup);
  launch_whole_scene_nodes(
      programs, setup, config, hosts, programs.circulation, "circulation",
      [&](int rank, RadiosityEngine& engine, const OccluderSet& occluders) -> CirculationProcessor& {
        return programs.circulation.emplace_back(
            setup, rank, owned, programs.runtimes[std::size_t(rank)], engine, occluders);
      });
}

void collect_circulation(const Scene& scene, const NodePrograms& programs, const PlatformConfig&,
                         SimulationResult& result) {
  const CirculationProcessor& first = programs.circulation.front();
  take_iterations(first, result);
  // Each patch as its owner holds it (the other nodes' copies of it are never updated).
  result.solution.assign(scene.patches.size(), PatchSolution{});
  result.patch_radiosity.assign(scene.patches.size(), Rgb(0.0));
  for (std::size_t rank = 0; rank < programs.circulation.size(); ++rank) {
    const RadiosityEngine& engine = programs.engines[rank];
    const std::vector<int>& owned = programs.circulation[rank].owned();
    result.held_patches.push_back(owned);
    for (const PatchSolution& p : engine.store().solution())
      if (std::find(owned.begin(), owned.end(), p.patch) != owned.end()) {
        result.solution[std::size_t(p.patch)] = p;
        result.patch_radiosity[std::size_t(p.patch)] = engine.patch_radiosity(p.patch);
      }
  }
}

}  // namespace

const MethodRegistry<Parallelisation>& parallelisations() {
  static const MethodRegistry<Parallelisation> registry(
      "parallelisation",
      {
          {"receivers",
           "the paper's: each radiosity processor holds a share of the patches and gathers "
           "each shooter's light at its own elements, sections 2.2 to 4",
           check_receivers,
           [](const ProgramSetup& setup, const CostModel& costs) {
             return plan_memory(setup, owned_patches(setup), costs);
           },
           launch_receivers, collect_receivers, ""},
          {"shooters",
           "the earlier scheme of sections 2.2 and 6: every node holds the whole scene, shoots "
           "its own shooter to every element, and the radiosity increments are summed over "
           "all nodes each iteration; V = 0",
           check_shooters, plan_shooter_memory, launch_shooters, collect_shooters,
           "increments_"},
          {"circulation",
           "a shooter-centred scheme built from the abstracts of Capin, Aykanat & Ozguc (Parallel "
           "Rendering Symposium 1993, after the paper; what is assumed: docs/model.md): static shares of the patches, every node's best patch shot at "
           "once, the light distributed by circulating each node's increments round a ring; "
           "V = 0",
           check_circulation,
           [](const ProgramSetup& setup, const CostModel& costs) {
             return plan_circulation_memory(setup, owned_patches(setup), costs);
           },
           launch_circulation, collect_circulation, "increments_"},
      });
  return registry;
}

bool parallelisation_writes_counter(const std::string& parallelisation, const std::string& counter) {
  // A counter some parallelisation claims by its prefix is written for the runs of the
  // parallelisations that claim it only.
  bool claimed = false;
  for (const Parallelisation& p : parallelisations().all())
    if (!p.counter_prefix.empty() && counter.rfind(p.counter_prefix, 0) == 0) {
      if (p.name == parallelisation) return true;
      claimed = true;
    }
  return !claimed;
}

}  // namespace ncube

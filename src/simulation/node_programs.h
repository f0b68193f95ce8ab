// The node programs of one radiosity run on the simulated machine (sections 2.2, 3 and 4): a
// runtime per node, a radiosity processor per rank with its engine (and its element store),
// V visibility processors per rank with their occluder shares, each an actor on its host.
#pragma once

#include <deque>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <simgrid/s4u/Engine.hpp>
#include <simgrid/s4u/Host.hpp>

#include "machine/cost_model.h"
#include "machine/platform_config.h"
#include "nodes/memory_plan.h"
#include "nodes/node_runtime.h"
#include "nodes/program_setup.h"
#include "nodes/circulation_processor.h"
#include "nodes/radiosity_processor.h"
#include "nodes/shooter_processor.h"
#include "nodes/visibility_processor.h"
#include "simulation/actor_exceptions.h"
#include "radiosity/radiosity_engine.h"
#include "simulation/host_machinery.h"
#include "simulation/simulation_config.h"

namespace ncube {

// Everything the node programs of one run are made of; lives until the run is over.
struct NodePrograms {
  std::deque<NodeRuntime> runtimes;  // in node order
  // Every runtime's SimGrid activities, when the environment asks for them
  // (nodes/activity_record.h; null otherwise).
  std::unique_ptr<ActivityRecord> activities;
  std::deque<RadiosityEngine> engines;
  std::deque<RadiosityProcessor> radiosity;  // in rank order; the master first
  std::deque<VisibilityProcessor> visibility;
  std::deque<ShooterProcessor> shooters;  // --parallelisation shooters: in rank order
  std::deque<CirculationProcessor> circulation;  // --parallelisation circulation: in rank order
  // An exception a node program threw (the host out of memory), rethrown after the run.
  ActorExceptions exceptions;
  // The occluder sets and the engines' host help (host_machinery.h); last, so that the
  // host's threads stop first.
  HostMachinery host;
};

// One runtime per node of `memory` (node order), each holding its planned bytes (and
// recording its activities when NCUBE_RECORD_ACTIVITIES names a file).
void create_runtimes(NodePrograms& programs, const std::vector<NodeMemory>& memory,
                     const PlatformConfig& platform, const CostModel& costs,
                     std::vector<TraceEvent>* trace);

// Builds the programs over the runtimes and creates their actors on `hosts`: radiosity
// processor `rank` owns the patches owned[rank]; the occluder sets are read-only and the
// same for every group, so they are built once and shared.
void launch_node_programs(NodePrograms& programs, const ProgramSetup& setup,
                          const std::vector<std::vector<int>>& owned,
                          const std::vector<simgrid::s4u::Host*>& hosts);

// Calls config.on_iteration (if set) as `master` (a RadiosityProcessor, or node 0 of the
// shooter-centred scheme) decides each iteration.
template <class Master>
void report_iterations(const Master& master, const SimulationConfig& config, double emitted_power) {
  if (!config.on_iteration) return;
  const double threshold = emitted_power * config.options.convergence_fraction;
  auto reported = std::make_shared<std::size_t>(0);
  simgrid::s4u::Engine::on_time_advance_cb([&master, &config, threshold, reported](double) {
    if (master.iteration_ends().size() == *reported) return;
    *reported = master.iteration_ends().size();
    config.on_iteration({int(*reported), master.largest_unshot_power(), threshold,
                         simgrid::s4u::Engine::get_clock()});
  });
}

// The solution as the radiosity processors' element stores hold it at the end (section 4):
// every patch's elements and radiosities and its radiosity (one entry per scene patch, in
// scene order), and the patches each radiosity processor holds (in rank order).
void collect_solution(const Scene& scene, const NodePrograms& programs,
                      std::vector<PatchSolution>& solution, std::vector<Rgb>& patch_radiosity,
                      std::vector<std::vector<int>>& held_patches);

// The radiosity of every level-0 element of the scene: a cut element's is the area-weighted
// mean of its descendants'.
std::vector<Rgb> level_zero_radiosity(const Scene& scene, const std::vector<PatchSolution>& solution);

// Why a node program did not reach its end ("" if every one did).
std::string unfinished_node(const NodePrograms& programs, double simulated_seconds);

}  // namespace ncube

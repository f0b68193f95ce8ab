// The parallelisations a run can choose (--parallelisation), each registered once
// (util/method_registry.h; docs/architecture.md, "How to add a method"): its name (the
// option's value and the result file's config.parallelisation), what the docs say of it, the
// configurations it refuses, each node's memory before the run, the node programs it places
// on the simulated machine, and what the run reports of them. The paper's program first
// (receivers: each radiosity processor holds a share of the patches and gathers at them),
// then the shooter-centred scheme it replaced (nodes/shooter_processor.h), then a
// shooter-centred scheme built from the abstracts of Çapın, Aykanat & Özgüç
// (nodes/circulation_processor.h; what is assumed: docs/model.md).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <simgrid/s4u/Host.hpp>

#include "machine/cost_model.h"
#include "machine/platform_config.h"
#include "nodes/memory_plan.h"
#include "scene/scene.h"
#include "simulation/node_programs.h"
#include "simulation/simulation_config.h"
#include "simulation/simulation_result.h"
#include "util/method_registry.h"

namespace ncube {

struct Parallelisation {
  std::string name;
  std::string doc;
  // Throws InputError (exit 2) for a configuration it cannot run (after the common checks).
  std::function<void(const Scene&, const SimulationConfig&)> check;
  // Every node's modeled bytes when its program starts, in node order.
  std::function<std::vector<NodeMemory>(const ProgramSetup&, const CostModel&)> plan_memory;
  // Builds the node programs over programs.runtimes, creates their actors on `hosts`, and
  // reports iterations as they end (config.on_iteration).
  std::function<void(NodePrograms&, const ProgramSetup&, const SimulationConfig&,
                     const std::vector<simgrid::s4u::Host*>&)>
      launch;
  // After the simulation: the iterations, the solution and what else the programs report.
  std::function<void(const Scene&, const NodePrograms&, const PlatformConfig&, SimulationResult&)>
      collect;
  // The prefix of the WorkCounts counters only this parallelisation counts ("": none): the
  // result file writes them for its runs only, so that the paper's runs keep their files.
  std::string counter_prefix;
};

// The paper's receivers first (the default), then shooters, then circulation.
const MethodRegistry<Parallelisation>& parallelisations();

// Whether the result file of a run with parallelisation `parallelisation` writes `counter`.
bool parallelisation_writes_counter(const std::string& parallelisation, const std::string& counter);

}  // namespace ncube

// What all node programs of one run share: the scene, where everyone sits, and the options
// of the algorithm.
#pragma once

#include <string>

#include "nodes/load_balancing.h"
#include "nodes/placement.h"
#include "radiosity/radiosity_engine.h"

namespace ncube {

// The options of the node programs (sections 2.2, 3 and 4), each with its one default here
// (the algorithm's, adaptive subdivision's among them, in ProgressiveOptions; load
// balancing's in BalancingOptions); the run's configuration (SimulationConfig) is made of
// them, and every program's setup holds them as configured.
struct ProgramOptions {
  ProgressiveOptions options;
  int block_size = 100;        // visibility points per message (section 3: "blocks of e.g. 100")
  bool pipelined = false;      // send the next block before using the answers of this one
  bool memory_cap = true;      // false: nodes never run out of memory (--unlimited-memory)
  BalancingOptions balancing;  // dynamic load balancing (section 4.2), off by default
  // --parallelisation: a name in parallelisations() (simulation/parallelisations.h): the
  // paper's receivers (the default) or the shooter-centred scheme it replaced.
  std::string parallelisation = "receivers";
  int shooters_per_iteration = 0;  // shooters: shots per iteration (0: one per node)

  // Whether the radiosity processors' loads can change during the run (sections 4.1, 4.2),
  // so that they travel with the shooter candidates.
  bool loads_change() const { return options.subdivision.enabled || balancing.enabled; }
};

struct ProgramSetup : ProgramOptions {
  ProgramSetup(const Scene& scene, Placement placement, const ProgramOptions& options,
               double emitted_power)
      : ProgramOptions(options), scene(scene), placement(placement), emitted_power(emitted_power) {}

  const Scene& scene;
  Placement placement;
  double emitted_power;  // of the whole scene, for the convergence test
};

}  // namespace ncube

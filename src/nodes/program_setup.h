// What all node programs of one run share: the scene, where everyone sits, and the options
// of the algorithm.
#pragma once

#include "nodes/placement.h"
#include "radiosity/radiosity_engine.h"

namespace ncube {

// The options of the node programs (sections 2.2 and 3), each with its one default here (the
// algorithm's in ProgressiveOptions); the run's configuration (SimulationConfig) is made of
// them, and every program's setup holds them as configured.
struct ProgramOptions {
  ProgressiveOptions options;
  int block_size = 100;    // visibility points per message (section 3: "blocks of e.g. 100")
  bool pipelined = false;  // send the next block before using the answers of this one
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

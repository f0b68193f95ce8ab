// What all node programs of one run share: the scene, where everyone sits, and the options
// of the algorithm.
#pragma once

#include "nodes/load_balancing.h"
#include "nodes/placement.h"
#include "radiosity/radiosity_engine.h"

namespace ncube {

struct ProgramSetup {
  const Scene& scene;
  Placement placement;
  ProgressiveOptions options;
  double emitted_power = 0.0;  // of the whole scene, for the convergence test
  int block_size = 100;        // visibility points per message (section 3: "blocks of e.g. 100")
  bool pipelined = false;      // send the next block before using the answers of this one
  bool memory_cap = true;      // false: nodes never run out of memory (--unlimited-memory)
  BalancingOptions balancing;  // section 4.2, off by default
  // Whether the radiosity processors' loads can change during the run (sections 4.1, 4.2),
  // so that they travel with the shooter candidates.
  bool loads_change() const { return options.subdivision.enabled || balancing.enabled; }
};

}  // namespace ncube

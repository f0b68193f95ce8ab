// What all node programs of one run share: the scene, where everyone sits, and the options
// of the algorithm.
#pragma once

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
};

}  // namespace ncube

// A visibility processor (paper section 3): stores the geometry of a 1/V share of the
// scene's patches and answers its radiosity processor's blocks of visibility points with
// one bit vector per point: which parts of the shooter its share of patches does not block.
#pragma once

#include "nodes/node_runtime.h"
#include "nodes/program_setup.h"
#include "visibility/occluder_set.h"

namespace ncube {

class VisibilityProcessor {
 public:
  VisibilityProcessor(const ProgramSetup& setup, NodeRuntime& runtime, const OccluderSet& share);

  void run();  // the actor's body: answer blocks until told to stop

 private:
  const ProgramSetup& setup_;
  NodeRuntime& runtime_;
  const OccluderSet& share_;
};

}  // namespace ncube

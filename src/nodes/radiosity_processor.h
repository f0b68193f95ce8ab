// A radiosity processor (paper section 2.2): owns patches and their elements, takes part in
// choosing the shooter, and shoots it to its own elements, tracing the visibility rays
// itself. With one radiosity processor and no visibility processors this is the sequential
// progressive-refinement program on one nCube2 node.
#pragma once

#include <vector>

#include "nodes/node_runtime.h"
#include "radiosity/radiosity_engine.h"

namespace ncube {

struct IterationRecord {
  int shooter = -1;
  double start = 0.0;  // simulated seconds
  double end = 0.0;
};

class RadiosityProcessor {
 public:
  RadiosityProcessor(NodeRuntime& runtime, RadiosityEngine& engine, const Occluders& occluders,
                     const ProgressiveOptions& options);

  void run();  // the actor's body: iterate until converged or the iteration limit

  const std::vector<IterationRecord>& iterations() const { return iterations_; }
  bool converged() const { return converged_; }

 private:
  void shoot(const Shooter& shooter);

  NodeRuntime& runtime_;
  RadiosityEngine& engine_;
  const Occluders& occluders_;
  ProgressiveOptions options_;
  double emitted_power_;
  std::vector<IterationRecord> iterations_;
  bool converged_ = false;
};

}  // namespace ncube

// The simulation plumbing beneath the node programs: every counted operation becomes CPU
// time on this node through the cost model, charged with this_actor::execute in batches.
// Messages and memory accounting join here (issue 3); the node programs only say what
// work they did.
#pragma once

#include <string>

#include "machine/cost_model.h"
#include "machine/platform_config.h"
#include "radiosity/work_counts.h"

namespace ncube {

struct NodeStats {
  int node = 0;
  std::string role;
  double compute_seconds = 0.0;
  WorkCounts counts;
};

class NodeRuntime {
 public:
  NodeRuntime(int node, std::string role, const PlatformConfig& platform, const CostModel& costs);

  // Runs the counted work on this node's CPU: one execute() for the whole batch.
  void compute(const WorkCounts& counts);
  double now() const;

  const NodeStats& stats() const { return stats_; }

 private:
  const PlatformConfig& platform_;
  const CostModel& costs_;
  NodeStats stats_;
};

}  // namespace ncube

#include "nodes/node_runtime.h"

#include <simgrid/s4u/Actor.hpp>
#include <simgrid/s4u/Engine.hpp>

namespace ncube {

NodeRuntime::NodeRuntime(int node, std::string role, const PlatformConfig& platform,
                         const CostModel& costs)
    : platform_(platform), costs_(costs) {
  stats_.node = node;
  stats_.role = std::move(role);
}

void NodeRuntime::compute(const WorkCounts& counts) {
  stats_.counts += counts;
  const double flops = costs_.flops(counts);
  if (flops <= 0.0) return;
  const double start = now();
  simgrid::s4u::this_actor::execute(flops);
  stats_.compute_seconds += now() - start;
}

double NodeRuntime::now() const { return simgrid::s4u::Engine::get_clock(); }

}  // namespace ncube

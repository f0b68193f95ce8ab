// The timeline of a run as a Chrome trace-event file (opens in Perfetto or chrome://tracing):
// one track per node, a slice for every stretch of computing, message overhead and waiting.
#pragma once

#include <string>

#include "simulation/simulation.h"

namespace ncube {

std::string trace_to_json(const SimulationResult& result);

}  // namespace ncube

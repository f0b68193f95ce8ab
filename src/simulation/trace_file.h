// The timeline of a run as a Chrome trace-event file (opens in Perfetto or chrome://tracing):
// one track per node, a slice for every stretch of computing, message overhead (each send and
// receive) and waiting, each with its arguments (docs/result-format.md, "The trace").
#pragma once

#include <climits>
#include <string>
#include <vector>

#include "simulation/simulation.h"

namespace ncube {

// Which events a trace keeps (--trace-iterations, --trace-nodes): by default all of them.
struct TraceWindow {
  // Iterations first to last, both included (from 1; 0 is the time before the first). Once
  // limited, the rendering phase's events (which belong to no iteration) are left out.
  bool iterations_limited = false;
  int first_iteration = 0, last_iteration = INT_MAX;
  std::vector<int> nodes;  // the nodes kept, ascending; empty: every node

  bool keeps_node(int node) const;
  bool keeps(const TraceEvent& event) const;
};

// "A:B" (iterations A to B), "A:" (A to the end), "A" (A alone); A <= B, from 0. Returns an
// empty string when `text` is one of these (and sets the window's iterations), else why not.
std::string parse_trace_iterations(const std::string& text, TraceWindow& window);
// "0,3,8-15": node numbers and ranges, ascending or not, from 0. Returns an empty string when
// `text` is such a list (and sets the window's nodes), else why not.
std::string parse_trace_nodes(const std::string& text, TraceWindow& window);

// Why the window names nodes or iterations a run cannot have, or "": a node at or past
// `node_count` (the run's R x (V + 1)), an iteration past `max_iterations` when the run is
// limited (>= 0). Known before the run.
std::string trace_window_problem(const TraceWindow& window, int node_count, int max_iterations);
// Why the window holds none of the `iterations` the run had (its first past the last that
// ran, e.g. a run that converged sooner), or "". Known after the run.
std::string trace_window_problem_after(const TraceWindow& window, int iterations, bool converged);

// The trace's size as the summary states it, and the size past which ./simulate warns and
// names the options that trim it (docs/cli.md, "--trace").
constexpr double kLargeTraceBytes = 10e6;

std::string trace_to_json(const SimulationResult& result, const TraceWindow& window = {});

}  // namespace ncube

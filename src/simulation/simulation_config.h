// The configuration of one simulated run (what ./simulate's options set).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "nodes/program_setup.h"
#include "nodes/render_setup.h"

namespace ncube {

struct IterationReport {
  int iterations_done = 0;
  double largest_unshot_power = 0.0;
  double threshold_power = 0.0;  // converged below this
  double simulated_seconds = 0.0;
};

// The configuration of one run: the node programs' options (ProgramOptions: the algorithm's,
// block size, pipelining, memory cap, load balancing), the machine's size and files, and what
// the run records.
struct SimulationConfig : ProgramOptions {
  int radiosity_processors = 1;   // R
  int visibility_processors = 0;  // V, per radiosity processor
  bool record_trace = false;
  std::string platform_file;
  std::string cost_model_file;
  // Called as each iteration is decided (the master's view); may be empty.
  std::function<void(const IterationReport&)> on_iteration;
  // SimGrid's own command-line arguments (--cfg=name:value, --log=...), given to its Engine.
  std::vector<std::string> simgrid_arguments;
  // The rendering phase after the radiosity run (section 2.3), when enabled.
  RenderOptions render;

  int node_count() const { return radiosity_processors * (visibility_processors + 1); }
};

}  // namespace ncube

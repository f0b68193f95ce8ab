// One simulated run: builds the nCube2 platform, places the node programs on it, runs
// SimGrid to the end and collects what the result file reports. One per process (SimGrid
// allows one Engine per process).
#pragma once

#include <functional>
#include <map>
#include <string>
#include <vector>

#include "machine/cost_model.h"
#include "machine/platform_config.h"
#include "nodes/load_balancing.h"
#include "nodes/node_runtime.h"
#include "radiosity/radiosity_engine.h"
#include "scene/scene.h"
#include "simulation/render_phase.h"

namespace ncube {

struct IterationReport {
  int iterations_done = 0;
  double largest_unshot_power = 0.0;
  double threshold_power = 0.0;  // converged below this
  double simulated_seconds = 0.0;
};

struct SimulationConfig {
  int radiosity_processors = 1;   // R
  int visibility_processors = 0;  // V, per radiosity processor
  ProgressiveOptions options;
  int block_size = 100;           // visibility points per message
  bool pipelined = false;         // send the next block before using this block's answers
  bool memory_cap = true;         // false: report the memory needed, never stop for it
  BalancingOptions balancing;     // dynamic load balancing (section 4.2), off by default
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

struct OutOfMemory {
  int node = -1;
  std::string role;
  double needed_bytes = 0.0;
  double available_bytes = 0.0;
};

struct SimulationResult {
  std::string status = "ok";  // or "out_of_memory", or "failed"
  OutOfMemory out_of_memory;  // when status is "out_of_memory"
  std::string failure;        // when status is "failed": why
  int iterations = 0;
  bool converged = false;
  double simulated_seconds = 0.0;
  std::vector<double> iteration_seconds;  // simulated seconds of each iteration, at the master
  std::vector<int> shooters;
  std::vector<Rgb> patch_radiosity;    // area-weighted mean of each patch's elements
  // Every patch's elements and radiosities as the radiosity processors hold them at the end
  // (one entry per scene patch, in scene order).
  std::vector<PatchSolution> solution;
  std::vector<Rgb> element_radiosity;  // per level-0 element of the scene (area-weighted mean
                                       // of its descendants when cut), for rendering
  std::vector<std::vector<int>> held_patches;  // per radiosity processor, at the end
  // At the master, per iteration: each radiosity processor's elements when it began
  // (subdivision or balancing on).
  std::vector<std::vector<long>> elements_per_iteration;
  long patches_moved = 0;  // by load balancing (section 4.2)
  WorkCounts counts;                   // all nodes together
  std::vector<NodeStats> nodes;        // in node order
  std::vector<TraceEvent> trace;       // when config.record_trace
  RenderResult render;                 // when config.render.enabled and the run got that far
  double host_seconds = 0.0;
  // The SimGrid settings the run used (the platform's defaults, overridden by --cfg).
  std::map<std::string, std::string> simgrid_config;
};

// Throws InputError for a configuration the simulator cannot run.
void check_configuration(const Scene& scene, const SimulationConfig& config,
                         const PlatformConfig& platform);

// The first node (in node order) whose modeled memory exceeds the platform's node memory;
// node -1 when every node fits. Needs the patches' element counts only, not the elements,
// so it can run before the host allocates them. The rendering phase's records are checked
// when it starts, from the solution (run_render_phase); here only the rest of its peak.
OutOfMemory first_node_out_of_memory(const Scene& scene, const SimulationConfig& config,
                                     const PlatformConfig& platform, const CostModel& costs);

// Runs the simulation. Unless a node is out of memory (config.memory_cap), the scene's
// elements must be built. Status "failed" when a node program did not reach its end (the
// simulation deadlocked) or a reported number is not finite; then `failure` says which.
SimulationResult run_simulation(const Scene& scene, const SimulationConfig& config,
                                const PlatformConfig& platform, const CostModel& costs);

}  // namespace ncube

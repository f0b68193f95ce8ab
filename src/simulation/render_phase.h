// The simulated rendering phase (paper section 2.3, --render-parallel) after the radiosity
// run: on the same simulated machine and nodes, its own node programs and statistics.
#pragma once

#include <vector>

#include <simgrid/s4u/Host.hpp>

#include "machine/cost_model.h"
#include "machine/platform_config.h"
#include "nodes/node_runtime.h"
#include "nodes/render_setup.h"
#include "render/image.h"
#include "scene/scene.h"

namespace ncube {

struct RenderNodeStats {
  NodeStats stats;                 // time, messages and peak memory of the phase
  int rows = 0;                    // picture rows of its part
  double rasterise_seconds = 0.0;  // counted rasterisation time (the partition's load)
  RenderCounts counts;
};

struct RenderResult {
  bool ran = false;
  double simulated_seconds = 0.0;  // from the end of the radiosity run to the picture at node 0
  std::vector<RenderNodeStats> nodes;  // in node order
  double imbalance = 0.0;  // max / mean of the nodes' rasterise_seconds
  Image picture;           // assembled at node 0
  std::string failure;     // a node that did not finish ("" if all did)
  // The phase did not start: this node's records, frame and pixels exceed its memory
  // (-1 when every node fits).
  int out_of_memory_node = -1;
  double out_of_memory_bytes = 0.0;  // what that node needs
};

// Throws InputError when the options cannot run on `nodes` nodes (hypercube distribution
// on a node count that is not a power of two).
void check_render_configuration(const RenderOptions& options, int nodes);

// Each node's peak bytes in the phase, from the records of `solution` (one entry per
// scene patch, in order) each node starts with.
std::vector<double> render_memory(const Scene& scene, const RenderOptions& options, int R, int V,
                                  const std::vector<PatchSolution>& solution,
                                  const CostModel& costs);

// The part of each node's peak that does not depend on the solution (frame share, finished
// rows, the picture at node 0): checked before the radiosity run, so that a picture the
// nodes cannot hold stops the run before it starts.
std::vector<double> render_memory_without_records(const RenderOptions& options, int R, int V,
                                                  const CostModel& costs);

// Runs the phase on `hosts` (the SimGrid Engine exists; the radiosity run is over) with the
// solution's records. With `memory_cap`, a node whose peak (render_memory) exceeds the
// platform's node memory stops the phase before it starts (out_of_memory_node).
// `held_patches`: each radiosity processor's patches at the end of the run (load
// balancing moves them, section 4.2); null: the starting partition.
RenderResult run_render_phase(const Scene& scene, const RenderOptions& options, int R, int V,
                              const std::vector<PatchSolution>& solution,
                              const std::vector<simgrid::s4u::Host*>& hosts,
                              const PlatformConfig& platform, const CostModel& costs,
                              bool memory_cap, std::vector<TraceEvent>* trace,
                              const std::vector<std::vector<int>>* held_patches = nullptr);

}  // namespace ncube

// What one simulated run reports (the result file's content: simulation/result_file.h).
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "counts/work_counts.h"
#include "nodes/node_role.h"
#include "nodes/node_runtime.h"
#include "scene/patch_mesh.h"
#include "scene/scene.h"
#include "simulation/render_phase.h"

namespace ncube {

struct OutOfMemory {
  int node = -1;
  NodeRole role = NodeRole::kRadiosity;
  double needed_bytes = 0.0;
  double available_bytes = 0.0;
};

// How a run ended: it ran to its end, a node was out of memory (before it started, or a
// radiosity processor that could not make its cuts, sections 4.1 and 4.2, or the rendering
// phase's records), or a node program did not reach its end or a number was not finite.
enum class RunStatus { kOk, kOutOfMemory, kFailed };
// The status's name in the result file: "ok", "out_of_memory", "failed".
const char* status_name(RunStatus status);

struct SimulationResult {
  RunStatus status = RunStatus::kOk;
  OutOfMemory out_of_memory;  // when status is kOutOfMemory
  std::string failure;        // when status is kFailed: why
  int iterations = 0;
  bool converged = false;
  double simulated_seconds = 0.0;
  std::vector<double> iteration_seconds;  // simulated seconds of each iteration, at the master
  std::vector<int> shooters;
  std::vector<Rgb> patch_radiosity;    // area-weighted mean of each patch's elements
  // Every patch's elements and radiosities as the radiosity processors hold them at the end
  // (one entry per scene patch, in scene order).
  std::vector<PatchSolution> solution;
  // The elements of the solution (after subdivision's cuts): the result file's
  // elements_at_end and the summary's.
  long elements_at_end() const {
    long elements = 0;
    for (const PatchSolution& p : solution) elements += long(p.cells.size());
    return elements;
  }
  std::vector<Rgb> element_radiosity;  // per level-0 element of the scene (area-weighted mean
                                       // of its descendants when cut), for rendering
  std::vector<std::vector<int>> held_patches;  // per radiosity processor, at the end
  // At the master, per iteration: each radiosity processor's elements when it began
  // (subdivision or balancing on).
  std::vector<std::vector<long>> elements_per_iteration;
  long patches_moved = 0;  // by load balancing (section 4.2)
  long transfer_messages = 0;   // the kPatches messages that moved them
  double transfer_bytes = 0.0;  // their modeled payload (headers not included)
  WorkCounts counts;                   // all nodes together
  // The host work counters (work_counts.h) the platform charges, so the result file writes
  // them: none on a platform that does not give their rates (the nCube2's result files).
  std::vector<std::string> host_counters_charged;
  std::vector<NodeStats> nodes;        // in node order
  std::vector<TraceEvent> trace;       // when config.record_trace
  RenderResult render;                 // when config.render.enabled and the run got that far
  double host_seconds = 0.0;
  // The SimGrid settings the run used (the platform's defaults, overridden by --cfg).
  std::map<std::string, std::string> simgrid_config;
  // Every node's SimGrid activities, when NCUBE_RECORD_ACTIVITIES names a file
  // (nodes/activity_record.h): the caller writes them, as it writes the result file.
  std::shared_ptr<const ActivityRecord> activities;
};

}  // namespace ncube

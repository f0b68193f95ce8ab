// Command-line options of ./simulate (docs/cli.md).
#pragma once

#include <string>
#include <vector>

#include "models/model_import.h"
#include "simulation/simulation.h"
#include "simulation/trace_file.h"

namespace ncube {

struct SimulateOptions {
  std::string scene_file;
  SimulationConfig config;
  std::string json_file;   // empty: no result file
  std::string image_file;  // empty: no picture
  std::string trace_file;  // empty: no timeline
  TraceWindow trace_window;  // which of the timeline's events --trace keeps
  std::string mesh_file;   // empty: no solution mesh
  std::string export_scene_file;  // empty: the imported model is not written as JSON
  ImportOptions import;    // how a model file becomes a scene (docs/scene-format.md)
  bool import_options_given = false;
  bool quiet = false;
  bool check_settings = false;  // --check-settings: check the SimGrid settings and stop
  bool list_inputs = false;     // --list-inputs: print the files the run reads and stop
  bool platform_nodes = false;  // --platform-nodes: print the platform's node count and stop
  std::vector<std::string> command_line;  // argv, for the result file's provenance
};

// Parses argv. Returns the exit code to stop with (0 after --help, kExitBadInput after a
// bad option, with the message printed) or -1 to go on.
int parse_simulate_options(int argc, char** argv, SimulateOptions& options);

// Finds the scene, the platform and the cost model by the one lookup rule
// (tools/input_lookup.h) and replaces each name by the path found. Throws InputError naming
// every place tried when one is nowhere.
void find_simulate_inputs(SimulateOptions& options);

// The repository root (for platforms/ and scenes/): $NCUBE_ROOT, else the source tree the
// binary was built from.
std::string repository_root();

}  // namespace ncube

#include "tools/simulate_options.h"

#include <CLI/CLI.hpp>
#include <cstdlib>
#include <filesystem>
#include <iostream>

#include "util/input_error.h"

namespace ncube {

std::string repository_root() {
  if (const char* root = std::getenv("NCUBE_ROOT")) return root;
  return NCUBE_SOURCE_DIR;
}

std::string resolve_scene_path(const std::string& name) {
  namespace fs = std::filesystem;
  if (fs::exists(name) || name.find('/') != std::string::npos) return name;
  const fs::path in_scenes = fs::path(repository_root()) / "scenes" / name;
  return fs::exists(in_scenes) ? in_scenes.string() : name;
}

int parse_simulate_options(int argc, char** argv, SimulateOptions& options) {
  const std::string root = repository_root();
  SimulationConfig& config = options.config;
  config.platform_file = root + "/platforms/ncube2.json";
  config.cost_model_file = root + "/platforms/cost_model.json";
  std::string ray_test = "all";

  CLI::App app{"Simulates the parallel progressive radiosity of Stuerzlinger & Wild (1994) on a "
               "modeled nCube2 hypercube.",
               "simulate"};
  app.get_formatter()->column_width(34);
  app.add_option("scene", options.scene_file,
                 "scene file (JSON); a bare name is also looked up in scenes/")
      ->required();
  app.add_option("--R", config.radiosity_processors, "radiosity processors")
      ->capture_default_str();
  app.add_option("--V", config.visibility_processors,
                 "visibility processors per radiosity processor")
      ->capture_default_str();
  app.add_option("--samples", config.options.samples,
                 "M, parts of the shooter (one ray each): a perfect square from 1 to 64")
      ->capture_default_str();
  app.add_option("--iterations", config.options.max_iterations,
                 "stop after N shots (-1: until converged)")
      ->capture_default_str();
  app.add_option("--convergence", config.options.convergence_fraction,
                 "converged when the largest unshot power is below this fraction of the "
                 "emitted power")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1.0));
  app.add_option("--ray-test", ray_test,
                 "how far the brute-force loop runs per ray: all (every other patch, "
                 "section 2.2) or first-blocker")
      ->capture_default_str()
      ->check(CLI::IsMember({"all", "first-blocker"}));
  app.add_flag("--skip-facing-away", config.options.skip_facing_away,
               "trace no rays from elements that cannot see the shooter's front (default: every "
               "element traces its rays, section 2.2)");
  app.add_option("--block-size", config.block_size,
                 "visibility points per message to a visibility processor (section 3)")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000000));
  app.add_flag("--pipelined", config.pipelined,
               "send the next block of points before using the answers of this one");
  bool unlimited_memory = false;
  app.add_flag("--unlimited-memory", unlimited_memory,
               "report each node's memory but never stop for lack of it");
  app.add_option("--platform", config.platform_file, "machine description")
      ->capture_default_str();
  app.add_option("--cost-model", config.cost_model_file, "flops per counted operation")
      ->capture_default_str();
  app.add_option("--json", options.json_file, "write the result file here");
  app.add_option("--image", options.image_file, "render the solution to this PNG file");
  app.add_option("--trace", options.trace_file,
                 "write every node's timeline as a Chrome trace-event file (Perfetto)");
  app.add_option("--image-width", options.image_width, "picture width in pixels")
      ->capture_default_str()
      ->check(CLI::Range(16, 8192));
  app.add_option("--image-height", options.image_height, "picture height in pixels")
      ->capture_default_str()
      ->check(CLI::Range(16, 8192));
  app.add_flag("--quiet", options.quiet, "print nothing but errors");
  app.add_option("--threads", config.options.host_threads,
                 "host threads for one run (0: all cores); results do not depend on it")
      ->capture_default_str()
      ->check(CLI::Range(0, 1024));

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    std::cout << app.help();
    return kExitOk;
  } catch (const CLI::ParseError& e) {
    std::cerr << "simulate: " << e.what() << "\n(see simulate --help)\n";
    return kExitBadInput;
  }
  config.memory_cap = !unlimited_memory;
  config.record_trace = !options.trace_file.empty();
  config.options.ray_policy =
      ray_test == "all" ? RayTestPolicy::kTestAllPatches : RayTestPolicy::kStopAtFirstBlocker;
  options.scene_file = resolve_scene_path(options.scene_file);
  return -1;
}

}  // namespace ncube

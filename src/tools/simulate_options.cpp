#include "tools/simulate_options.h"

#include <CLI/CLI.hpp>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <limits>
#include <regex>

#include "util/input_error.h"
#include "util/version.h"

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

namespace {

// Counts are written in decimal: CLI11 would read "010" as 8 (octal) and accept "0x10";
// both are almost surely typos in a command line of this program.
const CLI::Validator kDecimalInteger(
    [](std::string& text) -> std::string {
      static const std::regex decimal("-?(0|[1-9][0-9]{0,9})");
      if (std::regex_match(text, decimal)) return "";
      return "'" + text + "' is not a decimal integer (digits without leading zeros or prefixes)";
    },
    "INT");

// --convergence: a finite fraction in [kMinConvergence, 1]. The run stops when the largest
// unshot power falls below this fraction of the emitted power; each round of shots lowers
// it by about the mean reflectance, so far smaller fractions (or 0, NaN) would not stop.
constexpr double kMinConvergence = 1e-10;
const CLI::Validator kConvergenceFraction(
    [](std::string& text) -> std::string {
      char* end = nullptr;
      const double value = std::strtod(text.c_str(), &end);
      if (!text.empty() && *end == '\0' && value >= kMinConvergence && value <= 1.0) return "";
      return "'" + text + "' is not a number from 1e-10 to 1";
    },
    "FRACTION");

}  // namespace

int parse_simulate_options(int argc, char** argv, SimulateOptions& options) {
  const std::string root = repository_root();
  SimulationConfig& config = options.config;
  config.platform_file = root + "/platforms/ncube2.json";
  config.cost_model_file = root + "/platforms/cost_model.json";
  // The calibrated setup (docs/reproduce.md, "Calibration"): 64 samples per shooter.
  config.options.samples = 64;
  std::string ray_test = "all";
  std::string visibility = "brute-force";

  CLI::App app{"Simulates the parallel progressive radiosity of Stuerzlinger & Wild (1994) on a "
               "modeled nCube2 hypercube.",
               "simulate"};
  app.get_formatter()->column_width(34);
  app.add_option("scene", options.scene_file,
                 "scene file (JSON); a bare name is also looked up in scenes/")
      ->required();
  app.add_option("--R", config.radiosity_processors, "radiosity processors")
      ->capture_default_str()
      ->check(kDecimalInteger);
  app.add_option("--V", config.visibility_processors,
                 "visibility processors per radiosity processor")
      ->capture_default_str()
      ->check(kDecimalInteger);
  app.add_option("--samples", config.options.samples,
                 "M, parts of the shooter (one ray each): a perfect square from 1 to 64")
      ->capture_default_str()
      ->check(kDecimalInteger);
  app.add_option("--iterations", config.options.max_iterations,
                 "stop after N shots (-1: until converged)")
      ->capture_default_str()
      ->check(kDecimalInteger & CLI::Range(-1, std::numeric_limits<int>::max()));
  app.add_option("--convergence", config.options.convergence_fraction,
                 "converged when the largest unshot power is below this fraction of the "
                 "emitted power (1e-10 to 1)")
      ->capture_default_str()
      ->check(kConvergenceFraction);
  app.add_option("--ray-test", ray_test,
                 "how far the brute-force loop runs per ray: all (every other patch, "
                 "section 2.2) or first-blocker")
      ->capture_default_str()
      ->check(CLI::IsMember({"all", "first-blocker"}));
  app.add_option("--visibility", visibility,
                 "how rays find their blockers: brute-force (every patch, sections 2.2 and 3; "
                 "the calibrated setup) or octree (section 6: an octree over each node's "
                 "patches, the walk stops at the first blocker; --ray-test has no effect)")
      ->capture_default_str()
      ->check(CLI::IsMember({"brute-force", "octree"}));
  app.add_flag("--skip-facing-away", config.options.skip_facing_away,
               "trace no rays from elements that cannot see the shooter's front (default: every "
               "element traces its rays, section 2.2)");
  app.add_option("--block-size", config.block_size,
                 "visibility points per message to a visibility processor (section 3)")
      ->capture_default_str()
      ->check(kDecimalInteger & CLI::Range(1, 1000000));
  app.add_flag("--pipelined", config.pipelined,
               "send the next block of points before using the answers of this one");
  SubdivisionOptions& subdivision = config.options.subdivision;
  app.add_flag("--subdivide", subdivision.enabled,
               "adaptive subdivision (section 4.1): after each shot, cut the elements whose "
               "corner radiosities differ too much, recursively");
  app.add_option("--subdivide-contrast", subdivision.contrast,
                 "cut an element when (Ymax - Ymin) / (Ymax + Ymin) of its corner luminances "
                 "exceeds this")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1.0));
  app.add_option("--subdivide-max-level", subdivision.max_level,
                 "deepest element level (0: the scene's grid; each level cuts in four)")
      ->capture_default_str()
      ->check(kDecimalInteger & CLI::Range(0, kMaxCellLevel));
  app.add_option("--subdivide-min-area", subdivision.min_area,
                 "no element smaller than this (scene units squared)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1e300));
  app.add_flag("--balance", config.balancing.enabled,
               "dynamic load balancing (section 4.2): move patches with their elements from "
               "radiosity processors with significantly more elements, or short of memory");
  app.add_option("--balance-threshold", config.balancing.threshold,
                 "\"significantly\": more than (1 + this) x the mean element count")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1e6));
  bool unlimited_memory = false;
  app.add_flag("--unlimited-memory", unlimited_memory,
               "report each node's memory but never stop for lack of it");
  app.add_option("--platform", config.platform_file, "machine description")
      ->capture_default_str();
  app.add_option("--cost-model", config.cost_model_file, "flops per counted operation")
      ->capture_default_str();
  // An output option given an empty file name is an error, not "no output".
  const CLI::Validator kFileName(
      [](std::string& text) -> std::string { return text.empty() ? "the file name is empty" : ""; },
      "FILE");
  app.add_option("--json", options.json_file, "write the result file here")->check(kFileName);
  app.add_option("--image", options.image_file, "render the solution to this PNG file")
      ->check(kFileName);
  app.add_option("--trace", options.trace_file,
                 "write every node's timeline as a Chrome trace-event file (Perfetto)")
      ->check(kFileName);
  app.add_option("--image-width", config.render.width, "picture width in pixels")
      ->capture_default_str()
      ->check(kDecimalInteger & CLI::Range(16, 8192));
  app.add_option("--image-height", config.render.height, "picture height in pixels")
      ->capture_default_str()
      ->check(kDecimalInteger & CLI::Range(16, 8192));
  std::string render_parallel = "off", render_distribution = "hypercube";
  app.add_option("--render-parallel", render_parallel,
                 "after the radiosity run, simulate rendering the picture on all nodes "
                 "(section 2.3): blocks (N bands of rows) or scanlines (every N-th row)")
      ->capture_default_str()
      ->check(CLI::IsMember({"off", "blocks", "scanlines"}));
  app.add_option("--render-distribution", render_distribution,
                 "how the elements reach every node in the rendering phase: ring or hypercube")
      ->capture_default_str()
      ->check(CLI::IsMember({"ring", "hypercube"}));
  app.add_flag("--outline-elements", config.render.outline_elements,
               "draw each element's edges as thin dark lines in the picture (to see the mesh)");
  app.add_flag("--quiet", options.quiet, "print nothing but errors (no summary, no progress)");
  std::vector<std::string> cfg, log;
  app.add_option("--cfg", cfg, "a SimGrid setting, name:value (e.g. network/model:LV08); "
                 "overrides the platform's")->type_name("NAME:VALUE")->allow_extra_args(false);
  app.add_option("--log", log, "a SimGrid log setting, e.g. ncube_messages.thresh:debug "
                 "(categories: ncube_radiosity, ncube_visibility, ncube_render, ncube_messages)")
      ->type_name("SETTING")->allow_extra_args(false);
  app.set_version_flag("--version", [] {
    return "simulate " + code_version() + " (SimGrid " + simgrid_version() + ")";
  });
  app.add_option("--threads", config.options.host_threads,
                 "host threads for one run (0: all cores); results do not depend on it")
      ->capture_default_str()
      ->check(kDecimalInteger & CLI::Range(0, 1024));
  app.add_flag("--reference-visibility", config.options.reference_visibility,
               "answer every ray with the readable definitions alone (the paper's loop, or the "
               "octree walk), one host thread, no answer cache, no lookahead: slow, and the "
               "same result file as without it (docs/architecture.md)");

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    std::cout << app.help();
    return kExitOk;
  } catch (const CLI::CallForVersion& e) {
    std::cout << e.what() << "\n";
    return kExitOk;
  } catch (const CLI::ParseError& e) {
    std::cerr << "simulate: " << e.what() << "\n(see simulate --help)\n";
    return kExitBadInput;
  }
  for (const std::string& setting : cfg) config.simgrid_arguments.push_back("--cfg=" + setting);
  for (const std::string& setting : log) config.simgrid_arguments.push_back("--log=" + setting);
  options.command_line.assign(argv, argv + argc);
  config.memory_cap = !unlimited_memory;
  config.record_trace = !options.trace_file.empty();
  config.options.ray_policy =
      ray_test == "all" ? RayTestPolicy::kTestAllPatches : RayTestPolicy::kStopAtFirstBlocker;
  config.options.visibility =
      visibility == "octree" ? VisibilityMethod::kOctree : VisibilityMethod::kBruteForce;
  options.scene_file = resolve_scene_path(options.scene_file);
  config.render.enabled = render_parallel != "off";
  config.render.partition =
      render_parallel == "scanlines" ? RowPartition::kScanlines : RowPartition::kBlocks;
  config.render.distribution = render_distribution == "ring" ? RenderDistribution::kRing
                                                             : RenderDistribution::kHypercube;
  return -1;
}

}  // namespace ncube

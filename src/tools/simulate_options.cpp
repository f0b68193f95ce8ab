#include "tools/simulate_options.h"

#include <CLI/CLI.hpp>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <limits>

#include "radiosity/form_factor_methods.h"
#include "scene/scene_loader.h"
#include "simulation/parallelisations.h"
#include "simulation/trace_file.h"
#include "tools/input_lookup.h"
#include "tools/method_options.h"
#include "tools/option_table.h"
#include "tools/tool_exits.h"
#include "util/input_error.h"
#include "util/version.h"
#include "visibility/visibility_methods.h"

namespace ncube {

std::string repository_root() {
  if (const char* root = std::getenv("NCUBE_ROOT")) return root;
  return NCUBE_SOURCE_DIR;
}

void find_simulate_inputs(SimulateOptions& options) {
  const std::string root = repository_root();
  SimulationConfig& config = options.config;
  options.scene_file = find_input(options.scene_file, InputRole::kScene, root);
  config.platform_file = find_input(config.platform_file, InputRole::kPlatform, root);
  config.cost_model_file = find_input(config.cost_model_file, InputRole::kCostModel, root);
  // A folder a model may read: as given, else from the repository (steps 1 and 2 of the rule).
  for (std::string& folder : options.import.model_folders) {
    std::error_code error;
    if (!folder.empty() && folder[0] != '/' && !std::filesystem::exists(folder, error) &&
        std::filesystem::is_directory(std::filesystem::path(root) / folder, error))
      folder = (std::filesystem::path(root) / folder).string();
  }
}

int parse_simulate_options(int argc, char** argv, SimulateOptions& options) {
  const std::string root = repository_root();
  SimulationConfig& config = options.config;
  config.platform_file = root + "/platforms/ncube2.json";
  config.cost_model_file = root + "/platforms/cost_model.json";
  std::string ray_test = "all";
  std::string render_parallel = "off", render_distribution = "hypercube";

  CLI::App app{"Simulates the parallel progressive radiosity of Stuerzlinger & Wild (1994) on a "
               "modeled nCube2 hypercube.",
               "simulate"};
  app.get_formatter()->column_width(34);
  // Every option once, with its range and the result-file field that records it: the parser,
  // --describe-options, analysis/ncube/options.py and docs/cli.md's table all read this.
  OptionTable table(app);
  constexpr long kMaxInt = std::numeric_limits<int>::max();
  // Required, but for --check-settings (checked after parsing).
  table.positional("scene", options.scene_file,
                   "scene file (JSON) or model (OBJ, PLY, glTF): a path (from here, else from the "
                   "repository), or a name in scenes/ (scene3 or scene3.json)");
  table.integer("--R", config.radiosity_processors, 1, kMaxInt, "radiosity processors", "R");
  table.integer("--V", config.visibility_processors, 0, kMaxInt,
                "visibility processors per radiosity processor", "V");
  table.choice("--parallelisation", config.parallelisation, parallelisations().names(),
               "how the work is shared over the nodes: " + parallelisations().described(),
               "parallelisation");
  table.integer("--shooters-per-iteration", config.shooters_per_iteration, 0, kMaxInt,
                "--parallelisation shooters or circulation: patches shot at once per iteration, "
                "at most one per node (0: one per node)",
                "shooters_per_iteration");
  // The result file records them for shooter-centred runs only (so that the paper's runs
  // keep their files); the sweep tool compares them likewise (analysis/ncube/options.py):
  // recorded when the parallelisation is one of the listed.
  nlohmann::json shooter_centred = nlohmann::json::array();
  for (const std::string& name : parallelisations().names())
    if (name != parallelisations().paper_default().name) shooter_centred.push_back(name);
  for (const char* flag : {"--parallelisation", "--shooters-per-iteration"})
    table.annotate(flag, "recorded_when", {{"parallelisation", shooter_centred}});
  table.square("--samples", config.options.samples, 1, 64,
               "M, parts of the shooter (one ray each): a perfect square from 1 to 64", "samples");
  table.annotate("--samples", "shapes_rays", true);
  table.integer("--iterations", config.options.max_iterations, -1, kMaxInt,
                "stop after N shots (-1: until converged)", "max_iterations");
  // The run stops when the largest unshot power falls below this fraction of the emitted
  // power; each round of shots lowers it by about the mean reflectance, so far smaller
  // fractions (or 0) would not stop.
  table.number("--convergence", config.options.convergence_fraction, {1e-10, 1.0},
               "converged when the largest unshot power is below this fraction of the "
               "emitted power (1e-10 to 1)",
               "convergence_fraction");
  table.choice("--ray-test", ray_test, {"all", "first-blocker"},
               "how far the brute-force loop runs per ray: all (every other patch, "
               "section 2.2) or first-blocker",
               "ray_test");
  table.annotate("--ray-test", "shapes_rays", true);
  table.choice("--visibility", config.options.visibility, visibility_methods().names(),
               "how rays find their blockers: " + visibility_methods().described(),
               "visibility");
  table.annotate("--visibility", "shapes_rays", true);
  table.choice("--form-factors", config.options.form_factors, form_factor_methods().names(),
               "how a shooter's form factors are computed: " + form_factor_methods().described(),
               "form_factors");
  table.even("--hemicube-resolution", config.options.hemicube.resolution, kMinHemicubeResolution,
             kMaxHemicubeResolution,
             "hemicube: N, cells on a side of the top face (the side faces are N x N/2); even",
             "hemicube_resolution");
  std::string hemicube_placement = hemicube_placement_name(config.options.hemicube.placement);
  table.choice("--hemicube-placement", hemicube_placement, {"centre", "elements"},
               "hemicube: one at the shooter's centre (centre), or one at the centre of each "
               "of the shooter's elements, weighted by area (elements)",
               "hemicube_placement");
  // The hemicube's back faces: block, the default, as every run before the option; recorded
  // for `pass` runs only (the method's registration, FormFactorMethod::recorded_unless).
  std::string hemicube_back_faces = hemicube_back_faces_name(config.options.hemicube.back_faces);
  table.choice("--hemicube-back-faces", hemicube_back_faces, {"block", "pass"},
               "hemicube: a polygon seen from behind takes cells and hides what lies beyond it "
               "(block), or is culled and passes the light on (pass); it receives nothing "
               "either way",
               "hemicube_back_faces");
  // The reciprocity's guard: as computed, the default, as every run before the option;
  // recorded for `clamp` runs only, so that every earlier hemicube result file stays as it was.
  std::string hemicube_reciprocity = hemicube_reciprocity_name(config.options.hemicube.reciprocity);
  table.choice("--hemicube-reciprocity", hemicube_reciprocity, {"as-computed", "clamp"},
               "hemicube: a receiver's form factor to the shooter by reciprocity, which can "
               "come out above 1 for a small receiver near the eye, kept (as-computed) or taken "
               "as at most 1 (clamp, a guard assumed, not from a source); counted either way",
               "hemicube_reciprocity");
  // The result file records the method for every run but the paper's and each method's own
  // options for its runs only (so that the paper's runs keep their files); the sweep tool
  // compares them likewise and reads each method's rules (tools/method_options.h).
  annotate_form_factor_methods(table);
  table.flag("--skip-facing-away", config.options.skip_facing_away,
             "trace no rays from elements that cannot see the shooter's front (default: every "
             "element traces its rays, section 2.2)",
             "skip_facing_away");
  table.integer("--block-size", config.block_size, 1, 1000000,
                "visibility points per message to a visibility processor (section 3)",
                "block_size");
  table.flag("--pipelined", config.pipelined,
             "send the next block of points before using the answers of this one", "pipelined");
  bool unlimited_memory = false;
  // Recorded inverted, as the result file's memory_cap.
  table.flag("--unlimited-memory", unlimited_memory,
             "report each node's memory but never stop for lack of it", "memory_cap");
  SubdivisionOptions& subdivision = config.options.subdivision;
  table.flag("--subdivide", subdivision.enabled,
             "adaptive subdivision (section 4.1): after each shot, cut the elements whose "
             "corner radiosities differ too much, recursively",
             "subdivide");
  table.number("--subdivide-contrast", subdivision.contrast, {0.0, 1.0},
               "cut an element when (Ymax - Ymin) / (Ymax + Ymin) of its corner luminances "
               "exceeds this",
               "subdivide_contrast");
  table.integer("--subdivide-max-level", subdivision.max_level, 0, kMaxCellLevel,
                "deepest element level (0: the scene's grid; each level cuts in four)",
                "subdivide_max_level");
  table.number("--subdivide-min-area", subdivision.min_area, {0.0, 1e300},
               "no element smaller than this (scene units squared)", "subdivide_min_area");
  table.flag("--balance", config.balancing.enabled,
             "dynamic load balancing (section 4.2): move patches with their elements from "
             "radiosity processors with significantly more elements, or short of memory",
             "balance");
  table.number("--balance-threshold", config.balancing.threshold, {0.0, 1e6},
               "\"significantly\": more than (1 + this) x the mean element count",
               "balance_threshold");
  table.choice("--render-parallel", render_parallel, {"off", "blocks", "scanlines"},
               "after the radiosity run, simulate rendering the picture on all nodes "
               "(section 2.3): blocks (N bands of rows) or scanlines (every N-th row)",
               "render_parallel");
  table.choice("--render-distribution", render_distribution, {"ring", "hypercube"},
               "how the elements reach every node in the rendering phase: ring or hypercube",
               "render_distribution");
  table.integer("--image-width", config.render.width, 16, 8192, "picture width in pixels",
                "image_width");
  table.integer("--image-height", config.render.height, 16, 8192, "picture height in pixels",
                "image_height");
  table.flag("--outline-elements", config.render.outline_elements,
             "draw each element's edges as thin dark lines in the picture (to see the mesh)",
             "outline_elements");
  // A model file (OBJ, PLY, glTF) instead of a scene: docs/scene-format.md, "Importing models".
  ImportOptions& import = options.import;
  std::vector<CLI::Option*> import_options = {
      // Within [1e-100, 1e100] a model's squared lengths stay far from overflow and
      // underflow, as the scene loader's own scaling keeps them (docs/scene-format.md).
      table.number("--scale", import.scale, {1e-100, 1e100},
                   "model files: multiply every coordinate by this", ""),
      table.number("--element-size", import.element_size, {0.0, 1e300},
                   "model files: cut patches into elements about this long on a side (0: by "
                   "--element-budget)",
                   ""),
      table.integer("--element-budget", import.element_budget, 0, int(kMaxElementsPerScene),
                    "model files: elements over the whole scene, spread over the patches by "
                    "area (0: 16 per patch)",
                    ""),
      table.flag("--flip-faces", import.flip_faces,
                 "model files: turn every face around (normals that point inward)", ""),
      table.flag("--merge-coplanar", import.merge_coplanar,
                 "model files: merge two triangles of one material that make a planar convex "
                 "quadrilateral into one patch",
                 ""),
      table.setting("--light", import.lights, "NAME[=R,G,B]",
                    "model files: the material or mesh NAME emits R,G,B (default 1,1,1); "
                    "repeatable"),
      // A model reads only files in its own folder (docs/cli.md, "Input files").
      table.setting("--model-folder", import.model_folders, "DIR",
                    "model files: a folder besides the model's own whose files the model may "
                    "name (its MTL, glTF buffers); repeatable")};
  table.file("--export-scene", options.export_scene_file, "output",
             "model files: write the imported scene as the project's JSON");
  for (const char* flag : {"--scale", "--element-size", "--element-budget", "--flip-faces",
                           "--merge-coplanar", "--light", "--model-folder", "--export-scene"})
    table.annotate(flag, "applies_to", "model files");
  table.file("--platform", config.platform_file, "file",
             "machine description: a path (from here, else from the repository), or a name in "
             "platforms/ or platforms/machines/ (ncube2, cm5.xml)",
             "platforms/ncube2.json")
      ->capture_default_str();
  table.file("--cost-model", config.cost_model_file, "file",
             "flops per counted operation: a path, or a name in platforms/",
             "platforms/cost_model.json")
      ->capture_default_str();
  table.file("--json", options.json_file, "output", "write the result file here");
  table.file("--image", options.image_file, "output", "render the solution to this PNG file");
  table.file("--mesh", options.mesh_file, "output",
             "write the solution as a mesh (PLY): every element a polygon, vertex colours "
             "tone-mapped as the picture, raw radiosity as doubles");
  table.file("--trace", options.trace_file, "output",
             "write every node's timeline as a Chrome trace-event file (Perfetto)");
  std::string trace_iterations, trace_nodes;
  const auto trace_iterations_check = [](const std::string& text) {
    TraceWindow window;
    return parse_trace_iterations(text, window);
  };
  const auto trace_nodes_check = [](const std::string& text) {
    TraceWindow window;
    return parse_trace_nodes(text, window);
  };
  CLI::Option* trace_iterations_option = table.text(
      "--trace-iterations", trace_iterations, "A:B", trace_iterations_check,
      "--trace: keep only the events of iterations A to B (A: from A on; A alone; 0 is before "
      "the first), without the rendering phase's");
  CLI::Option* trace_nodes_option =
      table.text("--trace-nodes", trace_nodes, "LIST", trace_nodes_check,
                 "--trace: keep only the events of these nodes, e.g. 0,3,8-15");
  for (const char* flag : {"--trace-iterations", "--trace-nodes"})
    table.annotate(flag, "applies_to", "--trace");
  bool quiet = false;
  table.flag("--quiet", quiet, "print nothing but errors (no summary, no progress)", "");
  std::vector<std::string> cfg, log;
  table.setting("--cfg", cfg, "NAME:VALUE",
                "a SimGrid setting, name:value (e.g. network/model:LV08); overrides the "
                "platform's");
  table.setting("--log", log, "SETTING",
                "a SimGrid log setting, e.g. ncube_messages.thresh:debug (categories: "
                "ncube_radiosity, ncube_visibility, ncube_shooters, ncube_circulation, "
                "ncube_render, ncube_messages)");
  // At most 64: libgomp reserves a stack of several MB per thread and ends the process
  // (exit 1, no message of ours) when it cannot create one, e.g. 128 threads under a 1 GB
  // address-space limit; more threads than cores gains nothing anyway.
  table.integer("--threads", config.options.host_threads, 0, 64,
                "host threads for one run (0: all cores); results do not depend on it", "");
  table.flag("--reference-visibility", config.options.reference_visibility,
             "answer every ray with the readable definitions alone (the paper's loop, or the "
             "octree walk), one host thread, no answer cache, no lookahead: slow, and the "
             "same result file as without it (docs/architecture.md)",
             "");
  table.flag("--check-settings", options.check_settings,
             "check the SimGrid settings given (--cfg, --log) as a run would, then stop: exit "
             "0, printing 'output: PATH' for each file they would write, or 2 with the "
             "setting SimGrid refuses (no scene needed)",
             "");
  table.flag("--platform-nodes", options.platform_nodes,
             "read the platform (--platform) with every check a run makes, print its number "
             "of nodes and stop (no scene needed; the sweep tool counts a platform's nodes so)",
             "");
  table.flag("--list-inputs", options.list_inputs,
             "print every file the run would read (role, file, sha256) as JSON, each read "
             "through the same checks and limits, then stop without simulating",
             "");
  bool describe = false;
  table.flag("--describe-options", describe,
             "print every option (kind, default, range, choices, result-file field) as JSON",
             "");
  app.set_version_flag("--version", [] {
    return "simulate " + code_version() + " (SimGrid " + simgrid_version() + ")";
  });
  // The description needs no scene: answered before the parser asks for one.
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]) == "--describe-options") {
      std::cout << table.describe().dump(1) << "\n";
      return kExitOk;
    }
  }

  if (const auto ended = parse_command_line(app, "simulate", argc, argv)) return *ended;
  for (CLI::Option* option : import_options)
    options.import_options_given = options.import_options_given || option->count() > 0;
  if (options.scene_file.empty() && !options.check_settings && !options.platform_nodes) {
    std::cerr << "simulate: scene is required (see simulate --help)\n";
    return kExitBadInput;
  }
  for (CLI::Option* option : {trace_iterations_option, trace_nodes_option})
    if (option->count() > 0 && options.trace_file.empty()) {
      std::cerr << "simulate: " << option->get_name() << " applies to --trace FILE only\n";
      return kExitBadInput;
    }
  if (!trace_iterations.empty()) parse_trace_iterations(trace_iterations, options.trace_window);
  if (!trace_nodes.empty()) parse_trace_nodes(trace_nodes, options.trace_window);
  for (const std::string& setting : cfg) config.simgrid_arguments.push_back("--cfg=" + setting);
  for (const std::string& setting : log) config.simgrid_arguments.push_back("--log=" + setting);
  options.command_line.assign(argv, argv + argc);
  config.memory_cap = !unlimited_memory;
  config.record_trace = !options.trace_file.empty();
  config.options.ray_policy =
      ray_test == "all" ? RayTestPolicy::kTestAllPatches : RayTestPolicy::kStopAtFirstBlocker;
  options.quiet = quiet;
  config.options.hemicube.placement =
      hemicube_placement == "elements" ? HemicubePlacement::kElements : HemicubePlacement::kCentre;
  config.options.hemicube.back_faces =
      hemicube_back_faces == "pass" ? HemicubeBackFaces::kPass : HemicubeBackFaces::kBlock;
  config.options.hemicube.reciprocity = hemicube_reciprocity == "clamp"
                                            ? HemicubeReciprocity::kClamp
                                            : HemicubeReciprocity::kAsComputed;
  config.render.enabled = render_parallel != "off";
  config.render.partition =
      render_parallel == "scanlines" ? RowPartition::kScanlines : RowPartition::kBlocks;
  config.render.distribution = render_distribution == "ring" ? RenderDistribution::kRing
                                                             : RenderDistribution::kHypercube;
  return -1;
}

}  // namespace ncube

// ./simulate's whole command: its options read, its inputs checked, one simulated run of the
// paper's radiosity program on the modeled nCube2, its summary printed and its files written.
// main() (simulate_main.cpp) only turns what it throws into exit codes.
#include "tools/simulate_command.h"

#include <strings.h>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <new>
#include <string_view>

#include <xbt/virtu.h>

#include "machine/cost_model.h"
#include "machine/platform_config.h"
#include "machine/simgrid_outputs.h"
#include "machine/simgrid_platform_file.h"
#include "machine/simgrid_session.h"
#include "machine/simgrid_settings.h"
#include "models/model_import.h"
#include "models/solution_mesh.h"
#include "nodes/activity_record.h"
#include "radiosity/form_factor_methods.h"
#include "render/image.h"
#include "render/rasterizer.h"
#include "scene/scene_loader.h"
#include "simulation/iteration_time.h"
#include "simulation/provenance.h"
#include "simulation/result_file.h"
#include "simulation/trace_file.h"
#include "tools/input_lookup.h"
#include "tools/output_files.h"
#include "tools/progress.h"
#include "tools/simulate_options.h"
#include "tools/tool_exits.h"
#include "util/input_error.h"
#include "util/shown_text.h"

namespace {

// "1 node", "64 nodes".
std::string count_of(long long n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

// "33.0 MB", "0.41 MB": decimal megabytes, as docs/cli.md states trace sizes.
std::string megabytes(double bytes) {
  char text[32];
  std::snprintf(text, sizeof text, bytes < 1e6 ? "%.2f MB" : "%.1f MB", bytes / 1e6);
  return text;
}

// A path as the summary shows it: relative to the repository when it lies there.
std::string shown_path(const std::string& path) {
  const std::string root = ncube::repository_root() + "/";
  return ncube::shown_text(path.rfind(root, 0) == 0 ? path.substr(root.size()) : path);
}

// `out`: stdout, or stderr when an output file is standard output. The lines of the
// defaults' runs come first and keep their form; a line for a choice away from the default
// (platform aside, always named) is added only then (docs/cli.md, "Output").
void print_summary(std::FILE* out, const ncube::Scene& scene, const ncube::SimulationConfig& config,
                   const ncube::PlatformConfig& platform, const ncube::SimulationResult& r) {
  std::fprintf(out, "scene                 %s (%s, %s)\n", ncube::shown_text(scene.name).c_str(),
               count_of(long(scene.patches.size()), "patch", "patches").c_str(),
               count_of(scene.element_total(), "element", "elements").c_str());
  std::fprintf(out, "platform              %s (%s, %s)\n",
               ncube::shown_text(std::filesystem::path(config.platform_file).stem().string()).c_str(),
               shown_path(config.platform_file).c_str(),
               count_of(platform.node_count(), "node", "nodes").c_str());
  const std::string nodes = count_of(config.node_count(), "node", "nodes");
  // How the run's form-factor method is set and what it counted: its registration says.
  const ncube::FormFactorMethod& method = ncube::form_factor_methods().at(config.options.form_factors);
  std::fprintf(out, "configuration         R=%d V=%d on %s, %s\n", config.radiosity_processors,
               config.visibility_processors, nodes.c_str(), method.setting(config.options).c_str());
  const ncube::ProgramOptions defaults;
  if (config.options.visibility != defaults.options.visibility)
    std::fprintf(out, "visibility            %s\n", config.options.visibility.c_str());
  if (method.name != ncube::form_factor_methods().paper_default().name)
    std::fprintf(out, "form factors          %s\n", method.name.c_str());
  if (config.options.hemicube.back_faces != ncube::HemicubeBackFaces::kBlock)
    std::fprintf(out, "hemicube back faces   %s (seen from behind, a polygon is culled)\n",
                 ncube::hemicube_back_faces_name(config.options.hemicube.back_faces));
  if (config.options.hemicube.reciprocity != ncube::HemicubeReciprocity::kAsComputed)
    std::fprintf(out, "hemicube reciprocity  %s (a form factor to the shooter at most 1)\n",
                 ncube::hemicube_reciprocity_name(config.options.hemicube.reciprocity));
  std::fprintf(out, "status                %s\n", ncube::status_name(r.status));
  if (r.status == ncube::RunStatus::kOutOfMemory)
    std::fprintf(out, "                      node %d (%s processor) needs %.0f bytes, has %.0f\n",
                 r.out_of_memory.node, ncube::role_name(r.out_of_memory.role),
                 r.out_of_memory.needed_bytes, r.out_of_memory.available_bytes);
  std::fprintf(out, "iterations            %d (%s)\n", r.iterations,
               r.converged ? "converged" : "not converged");
  if (config.parallelisation != defaults.parallelisation)
    std::fprintf(out, "parallelisation       %s, %s\n", config.parallelisation.c_str(),
                 count_of(long(r.shooters.size()), "shot", "shots").c_str());
  if (config.options.subdivision.enabled) {
    std::fprintf(out, "subdivision           %ld elements at the end (%ld at the start)\n",
                 r.elements_at_end(), long(scene.element_total()));
  }
  if (config.balancing.enabled)
    std::fprintf(out, "load balancing        %s moved in %s (%.0f bytes)\n",
                 count_of(r.patches_moved, "patch", "patches").c_str(),
                 count_of(r.transfer_messages, "message", "messages").c_str(), r.transfer_bytes);
  std::fprintf(out, "simulated seconds     %.3f in all\n", r.simulated_seconds);
  if (const std::optional<double> per_iteration = ncube::seconds_per_iteration(r.iteration_seconds)) {
    const int measured = ncube::iterations_measured(r.iteration_seconds);
    if (measured == 1)
      std::fprintf(out, "seconds per iteration %.3f (1 iteration, all that ran)\n", *per_iteration);
    else
      std::fprintf(out, "seconds per iteration %.3f (mean of the first %d iterations%s)\n",
                   *per_iteration, measured,
                   r.iterations >= ncube::kIterationsPerMeasure ? "" : ", all that ran");
  }
  const auto [counted, counts] = method.counted(r.counts);
  std::fprintf(out, "%-21s %s\n", counted.c_str(), counts.c_str());
  if (r.render.ran)
    std::fprintf(out, "rendering (%s, %s)  %.3f simulated seconds, rasterisation imbalance %.3f\n",
                 ncube::row_partition_name(config.render.partition),
                 ncube::render_distribution_name(config.render.distribution),
                 r.render.simulated_seconds, r.render.imbalance);
  std::fprintf(out, "host seconds          %.3f\n", r.host_seconds);
}

}  // namespace

namespace ncube {

int simulate_command(int argc, char** argv) {
  ncube::SimulateOptions options;
  const int parse_status = ncube::parse_simulate_options(argc, argv, options);
  if (parse_status >= 0) return parse_status;
  // The files SimGrid would write (log appenders, the trace) are outputs like --json.
  const ncube::SimgridOutputs simgrid_outputs(options.config.simgrid_arguments);
  std::vector<ncube::OutputFiles::Output> simgrid_files;
  for (const ncube::SimgridOutput& output : simgrid_outputs.outputs())
    simgrid_files.push_back({output.setting, output.path});
  // SimGrid ends the process on a setting it refuses: each is tried in a child first.
  ncube::check_simgrid_settings(options.config.simgrid_arguments);
  if (options.check_settings) {
    // Their paths as a run checks them, against the files the command line names.
    // The files found as a run would find them; one that is nowhere is named as given (a
    // missing input is the run's error, not the settings').
    std::vector<std::string> named = simgrid_outputs.inputs();
    for (const auto& [file, role] :
         {std::pair{&options.scene_file, ncube::InputRole::kScene},
          std::pair{&options.config.platform_file, ncube::InputRole::kPlatform},
          std::pair{&options.config.cost_model_file, ncube::InputRole::kCostModel}}) {
      if (file->empty()) continue;
      try {
        named.push_back(ncube::find_input(*file, role, ncube::repository_root()));
      } catch (const ncube::InputError&) {
        named.push_back(*file);
      }
    }
    ncube::OutputFiles checked(simgrid_files, named);
    // Each file the settings would make SimGrid write, one line each: the sweep tool refuses
    // a cell's settings that write outside its results folder (docs/sweeps.md, "What runs").
    for (const ncube::SimgridOutput& output : simgrid_outputs.outputs())
      std::cout << "output: " << ncube::shown_text(output.path) << "\n";
    return ncube::kExitOk;
  }
  if (options.platform_nodes) {  // the platform alone, found and read as a run finds and reads it
    options.config.platform_file = ncube::find_input(options.config.platform_file,
                                                     ncube::InputRole::kPlatform,
                                                     ncube::repository_root());
    if (ncube::is_simgrid_platform_file(options.config.platform_file))
      ncube::simgrid_engine(simgrid_outputs.engine_arguments(
          [](const std::string&) { return std::string("/dev/null"); }));
    const ncube::PlatformConfig platform = ncube::load_platform_config(
        options.config.platform_file, options.config.simgrid_arguments);
    std::cout << platform.node_count() << "\n";
    return ncube::kExitOk;
  }
  ncube::find_simulate_inputs(options);
  // Elements are built only after the memory check: a scene far too large for the modeled
  // machine is refused (exit 3) before the host allocates it.
  // A model file is imported into the project's scene JSON, then loaded (and checked) as a
  // scene file would be.
  const bool model = ncube::is_model_file(options.scene_file);
  if (!model && (options.import_options_given || !options.export_scene_file.empty()))
    throw ncube::InputError(options.scene_file + ": --scale, --element-size, --element-budget, "
                            "--flip-faces, --light and --export-scene apply to model files "
                            "(.obj, .ply, .gltf, .glb) only");
  // The mesh is PLY whatever the name; a name promising another format is refused.
  const std::string mesh_extension = std::filesystem::path(options.mesh_file).extension().string();
  for (const char* other : {".obj", ".gltf", ".glb", ".stl", ".fbx", ".dae", ".off", ".x3d"})
    if (strcasecmp(mesh_extension.c_str(), other) == 0)
      throw ncube::InputError("--mesh " + options.mesh_file + ": only PLY is written (name it .ply)");
  // The picture is PNG whatever the name (no JPEG encoder is linked): a name promising another
  // format is refused. A name without an extension ("-", /dev/stdout, "picture") is taken.
  const std::string image_extension = std::filesystem::path(options.image_file).extension().string();
  if (!image_extension.empty() && strcasecmp(image_extension.c_str(), ".png") != 0)
    throw ncube::InputError("--image " + options.image_file + ": only PNG is written (name it .png)");
  ncube::ImportSummary imported;
  std::string imported_text;  // the imported scene's JSON, kept for --export-scene only
  const auto import = [&options, &imported, &imported_text] {
    // The document is checked as it is, not written out and read again, and lives only until
    // it is a scene: a large model is not held twice during the run.
    const nlohmann::json document = ncube::import_model(options.scene_file, options.import, imported);
    if (!options.export_scene_file.empty()) imported_text = document.dump(1) + "\n";
    return ncube::scene_from_document(document, options.scene_file, ncube::SceneElements::kLater);
  };
  ncube::Scene scene =
      model ? import() : ncube::load_scene(options.scene_file, ncube::SceneElements::kLater);
  // A JSON platform is read before any Engine exists (its settings are checked in child
  // processes). A platform file never chooses where anything is written: it cannot name a
  // trace's file (platform_setting_problem), and its own tracing settings shape only a trace
  // the command line asks for (they then join the command line's); a platform that turns
  // tracing on by itself writes it nowhere, as a SimGrid platform file's <config> does
  // (engine_arguments names /dev/null). A SimGrid platform file is read by the Engine, after
  // the outputs are checked (SimGrid opens log files as its Engine starts).
  const bool simgrid_platform = ncube::is_simgrid_platform_file(options.config.platform_file);
  std::optional<ncube::PlatformConfig> json_platform;
  std::vector<std::string> run_settings;
  if (!simgrid_platform) {
    json_platform =
        ncube::load_platform_config(options.config.platform_file, options.config.simgrid_arguments);
    bool command_line_traces = false;
    for (const ncube::SimgridOutput& output : simgrid_outputs.outputs())
      command_line_traces |= output.setting.rfind("--cfg=tracing", 0) == 0;
    for (const auto& [name, value] : json_platform->simgrid_config)
      if (command_line_traces && name.rfind("tracing", 0) == 0)
        run_settings.push_back("--cfg=" + name + ":" + value);
  }
  run_settings.insert(run_settings.end(), options.config.simgrid_arguments.begin(),
                      options.config.simgrid_arguments.end());
  const ncube::SimgridOutputs run_simgrid_outputs(run_settings);
  std::vector<std::string> scene_parts;  // what a model read besides itself (MTL, buffers)
  for (const std::string& file : imported.files)
    if (file != options.scene_file) scene_parts.push_back(file);
  const ncube::RunInputs inputs{options.command_line, options.scene_file,
                                options.config.platform_file, options.config.cost_model_file,
                                scene_parts};
  if (options.list_inputs) {  // writes nothing: SimGrid's files, if any, go to /dev/null
    if (simgrid_platform)
      ncube::simgrid_engine(run_simgrid_outputs.engine_arguments(
          [](const std::string&) { return std::string("/dev/null"); }));
    const ncube::PlatformConfig platform =
        simgrid_platform ? ncube::load_platform_config(options.config.platform_file,
                                                       options.config.simgrid_arguments)
                         : *json_platform;
    ncube::load_cost_model(options.config.cost_model_file);
    std::cout << ncube::input_listing(inputs, platform).dump(1) << "\n";
    return ncube::kExitOk;
  }
  // Every output is checked (and its temporary file made) before SimGrid's Engine exists. No
  // output may be a file the run reads, nor one the model names (its textures).
  std::vector<std::string> read_files = {options.scene_file, options.config.platform_file,
                                         options.config.cost_model_file};
  read_files.insert(read_files.end(), imported.files.begin(), imported.files.end());
  read_files.insert(read_files.end(), imported.named_unread.begin(), imported.named_unread.end());
  read_files.insert(read_files.end(), run_simgrid_outputs.inputs().begin(),
                    run_simgrid_outputs.inputs().end());
  std::vector<ncube::OutputFiles::Output> wanted = {
      {"--json", options.json_file},
      {"--trace", options.trace_file},
      {"--image", options.image_file},
      {"--mesh", options.mesh_file},
      {"--export-scene", options.export_scene_file},
      {"NCUBE_RECORD_ACTIVITIES", ncube::ActivityRecord::requested_path()}};
  for (const ncube::SimgridOutput& output : run_simgrid_outputs.outputs())
    wanted.push_back({output.setting, output.path});
  ncube::OutputFiles outputs(wanted, read_files);
  const auto print_model = [&options, &imported, &outputs] {
    if (options.quiet) return;
    std::fprintf(outputs.uses_standard_output() ? stderr : stdout,
                 "model                 %ld faces -> %ld patches (%ld split into triangles, %ld "
                 "degenerate dropped, %ld pairs merged), %s read\n",
                 imported.faces, imported.patches, imported.split, imported.degenerate,
                 imported.merged, count_of(long(imported.files.size()), "file", "files").c_str());
  };
  // --export-scene with no output of a run (--json, --image, --mesh, --trace, SimGrid's
  // files, an activity record): the scene is written without simulating, and the summary
  // says so (docs/cli.md, "--export-scene").
  std::size_t run_outputs = 0;
  for (const ncube::OutputFiles::Output& output : wanted)
    run_outputs += output.option != "--export-scene" && !output.path.empty();
  if (model && !options.export_scene_file.empty() && run_outputs == 0) {
    outputs.write("--export-scene", imported_text);
    outputs.commit();
    print_model();
    if (!options.quiet) {
      std::FILE* out = outputs.uses_standard_output() ? stderr : stdout;
      std::fprintf(out, "scene                 %s (%s, %s)\n", ncube::shown_text(scene.name).c_str(),
                   count_of(long(scene.patches.size()), "patch", "patches").c_str(),
                   count_of(scene.element_total(), "element", "elements").c_str());
      std::fprintf(out, "simulation            none: --export-scene alone writes the scene (add "
                        "--json, --image, --mesh or --trace to run it too)\n");
      for (const ncube::OutputFiles::Output& written : outputs.written())
        std::fprintf(out, "written               %s (%s)\n", ncube::shown_text(written.path).c_str(),
                     written.option.c_str());
    }
    return ncube::kExitOk;
  }
  // SimGrid writes its files to their temporary files; the arguments the result file records
  // stay the user's.
  ncube::simgrid_engine(run_simgrid_outputs.engine_arguments(
      [&outputs](const std::string& setting) { return outputs.writer_path(setting); }));
  // The command line a Paje trace's header shows: the user's settings, not temporary files.
  simgrid::xbt::cmdline = {"simulate"};
  for (const std::string& argument : options.config.simgrid_arguments)
    simgrid::xbt::cmdline.push_back(argument);
  const ncube::PlatformConfig platform =
      simgrid_platform ? ncube::load_platform_config(options.config.platform_file,
                                                     options.config.simgrid_arguments)
                       : *json_platform;
  const ncube::CostModel costs = ncube::load_cost_model(options.config.cost_model_file);
  ncube::check_configuration(scene, options.config, platform);
  // A trace filter naming nodes or iterations the run does not have would write an empty or
  // partial trace without a word.
  if (const std::string problem = ncube::trace_window_problem(
          options.trace_window, options.config.node_count(), options.config.options.max_iterations);
      !problem.empty())
    throw ncube::InputError(problem);
  if (!options.config.memory_cap ||
      ncube::first_node_out_of_memory(scene, options.config, platform, costs).node < 0)
    scene.build_elements();

  std::optional<ncube::Progress> progress;
  if (!options.quiet && ncube::stderr_is_terminal()) {
    progress.emplace(stderr, options.config.options.max_iterations);
    options.config.on_iteration = [&progress](const ncube::IterationReport& r) { progress->report(r); };
  }
  const ncube::SimulationResult result =
      ncube::run_simulation(scene, options.config, platform, costs);
  progress.reset();
  if (result.status == ncube::RunStatus::kOk)
    if (const std::string problem = ncube::trace_window_problem_after(
            options.trace_window, result.iterations, result.converged);
        !problem.empty())
      throw ncube::InputError(problem);
  nlohmann::json result_json = ncube::result_to_json(scene, options.config, result);
  result_json["provenance"] = ncube::provenance_to_json(inputs, scene, platform, costs, result);
  if (model) print_model();
  if (!options.quiet)
    print_summary(outputs.uses_standard_output() ? stderr : stdout, scene, options.config, platform,
                  result);
  if (!options.json_file.empty()) outputs.write("--json", result_json.dump(1) + "\n");
  std::size_t trace_bytes = 0;
  if (!options.trace_file.empty()) {
    const std::string trace = ncube::trace_to_json(result, options.trace_window);
    trace_bytes = trace.size();
    outputs.write("--trace", trace);
  }
  if (!options.image_file.empty() && result.status == ncube::RunStatus::kOk)  // the simulated phase's picture if it ran
    outputs.write("--image", ncube::encode_png(result.render.ran ? result.render.picture
                                                                 : ncube::render_solution(
                                 scene, scene.camera, result.solution,
                                 options.config.render.width, options.config.render.height,
                                 options.config.render.outline_elements)));
  if (!options.export_scene_file.empty())
    outputs.write("--export-scene", imported_text);
  if (result.activities)
    result.activities->write(
        [&outputs](std::string_view bytes) { outputs.write("NCUBE_RECORD_ACTIVITIES", bytes); });
  if (!options.mesh_file.empty() && result.status == ncube::RunStatus::kOk)
    outputs.write("--mesh", ncube::solution_mesh_ply(
                                scene, result.solution,
                                ncube::solution_exposure(scene, scene.camera, result.solution,
                                                         options.config.render.width,
                                                         options.config.render.height)));
  outputs.commit();
  if (!options.quiet) {
    for (const ncube::OutputFiles::Output& written : outputs.written())
      std::fprintf(outputs.uses_standard_output() ? stderr : stdout, "written               %s (%s)%s\n",
                   ncube::shown_text(written.path).c_str(), written.option.c_str(),
                   written.option == "--trace" ? (": " + megabytes(trace_bytes)).c_str() : "");
    // A whole run's trace grows with nodes x iterations (scene2, R=8 V=7, 20 iterations:
    // 33 MB): past kLargeTraceBytes the user is told how to keep a part.
    if (trace_bytes > ncube::kLargeTraceBytes)
      std::fprintf(stderr,
                   "simulate: warning: the trace is %s (over %s): --trace-iterations A:B and "
                   "--trace-nodes LIST keep only those iterations and nodes\n",
                   megabytes(trace_bytes).c_str(), megabytes(ncube::kLargeTraceBytes).c_str());
  }
  if (result.status == ncube::RunStatus::kOutOfMemory) {
    std::fprintf(stderr, "simulate: node %d (%s processor) is out of memory: needs %.0f bytes, has %.0f\n",
                 result.out_of_memory.node, ncube::role_name(result.out_of_memory.role),
                 result.out_of_memory.needed_bytes, result.out_of_memory.available_bytes);
    return ncube::kExitOutOfMemory;
  }
  if (result.status == ncube::RunStatus::kFailed) {
    std::fprintf(stderr, "simulate: the simulation failed: %s\n", result.failure.c_str());
    return ncube::kExitSimulationFailed;
  }
  return ncube::kExitOk;
}

int simulate_main(int argc, char** argv) {
  // Every exception ends in one message and its own exit code (docs/cli.md); the output
  // files are removed as the stack unwinds.
  return run_tool("simulate", [&] { return simulate_command(argc, argv); });
}

}  // namespace ncube

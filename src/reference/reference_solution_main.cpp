// build/reference_solution SCENE --samples K --out ref.json — the accuracy reference of
// docs/accuracy.md: a converged element solution from form factors integrated over both
// elements, with its self-agreement (K/4 against K points per element) in the file.
#include <strings.h>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <new>
#include <thread>

#include <CLI/CLI.hpp>

#include "models/solution_mesh.h"
#include "reference/area_form_factors.h"
#include "reference/radiosity_solve.h"
#include "reference/reference_budget.h"
#include "reference/reference_file.h"
#include "reference/solution_error.h"
#include "reference/structure_solution.h"
#include "render/rasterizer.h"
#include "scene/patch_mesh.h"
#include "scene/scene_loader.h"
#include "tools/output_files.h"
#include "tools/tool_exits.h"
#include "util/input_error.h"
#include "util/input_file.h"

namespace {

namespace fs = std::filesystem;
using namespace ncube;

std::string resolve_scene(const std::string& name) {
  std::error_code error;
  if (fs::exists(name, error)) return name;
  for (const std::string& candidate : {name, name + ".json"}) {
    const fs::path in_scenes = fs::path(NCUBE_SOURCE_DIR) / "scenes" / candidate;
    if (fs::exists(in_scenes, error)) return in_scenes.string();
  }
  return name;
}

// The memory and the rays of the run, worked out before anything is taken (issue 37, item 4;
// docs/accuracy.md, "The command"): more memory than the host has is exit 6, more rays than
// --max-rays exit 2, each in one line; else the estimate is printed first.
void check_budget(const Scene& fine, int side, int threads, double max_rays, bool quiet) {
  const long long pairs = reference::pairs_of(fine);
  const double bytes = double(pairs) * reference::kBytesPerPair +
                       double(fine.elements.size()) * side * side * reference::kBytesPerPoint;
  const double available = reference::host_memory_available();
  if (bytes > available)
    throw HostMemoryError("the form factors of " + std::to_string(fine.elements.size()) +
                          " parts (" + std::to_string(pairs) + " pairs) need about " +
                          reference::budget_bytes(bytes) + ", the host has " +
                          reference::budget_bytes(available) +
                          " available: a smaller --refine or scene");
  const reference::ReferenceBudget budget = reference::reference_budget(fine, side);
  const int cores = threads > 0 ? threads : std::max(1, int(std::thread::hardware_concurrency()));
  const std::string estimate =
      std::to_string(budget.parts) + " parts, " + std::to_string(budget.pairs) + " pairs (" +
      std::to_string(budget.near_pairs) + " near): at most " + reference::budget_rays(budget.rays) +
      " rays over K and K/4, about " + reference::budget_bytes(budget.bytes) + " of memory and " +
      reference::budget_time(budget.host_seconds / cores) + " on " + std::to_string(cores) +
      (cores == 1 ? " thread" : " threads");
  if (budget.rays > max_rays)
    throw InputError("--max-rays " + reference::budget_rays(max_rays) + ": the run would take " +
                     estimate + "; a smaller --samples or --refine, or a larger --max-rays");
  if (!quiet) std::printf("estimate: %s\n", estimate.c_str());
  std::fflush(stdout);
}


// The solution as ./simulate's --mesh writes one: the scene's own grid, patch by patch in
// scene order (Scene::build_elements: row j, then column i), as a run without --subdivide
// hands its solution to the mesh.
std::string mesh_text(const Scene& scene, const std::vector<Rgb>& radiosity) {
  std::vector<PatchSolution> solution;
  for (std::size_t p = 0; p < scene.patches.size(); ++p) {
    const Patch& patch = scene.patches[p];
    PatchSolution& s = solution.emplace_back();
    s.patch = int(p);
    for (int j = 0; j < patch.nv; ++j)
      for (int i = 0; i < patch.nu; ++i) {
        s.cells.push_back({0, i, j});
        s.radiosity.push_back(radiosity[std::size_t(patch.first_element + j * patch.nu + i)]);
      }
  }
  return solution_mesh_ply(scene, solution, solution_exposure(scene, scene.camera, solution, 800, 600));
}

// ---- The exact structure (issue 38 item 3; docs/accuracy.md, "The error taken apart"):
// --structure patches|elements solves ./simulate's own structure with exact form factors
// (structure_solution.h) instead of the reference. Its own block: the options above are
// shared, --refine has no meaning here (the structure is the scene's own mesh).
int run_structure(const Scene& scene, const std::string& scene_file, reference::Structure structure,
                  int samples, int threads, bool quiet, const std::string& mesh_path,
                  OutputFiles& outputs) {
  const auto start = std::chrono::steady_clock::now();
  reference::StructureRun run;
  run.scene_file = fs::path(scene_file).filename().string();
  run.scene_sha256 = input_sha256(scene_file, kSceneFile);
  run.structure = structure;
  run.samples = samples;
  run.check_samples = samples / 4;
  const Scene shooters = reference::shooter_scene(scene, structure);
  const auto solve = [&](int points, reference::StructureStats& stats) {
    reference::StructureOptions options;
    options.side = int(std::lround(std::sqrt(double(points))));
    options.threads = threads;
    const bool eye = structure == reference::Structure::kHemicubeCentre ||
                     structure == reference::Structure::kHemicubeElements;
    const reference::StructureRows rows =
        eye ? reference::eye_form_factors(shooters, structure, options, &stats)
            : reference::structure_form_factors(shooters, options, &stats);
    if (eye && points == samples) run.above_one = reference::entries_above_one(rows);
    return reference::solve_structure(shooters, rows);
  };
  const reference::StructureSolve check = solve(run.check_samples, run.check_stats);
  run.solve = solve(samples, run.stats);
  const reference::SolutionError agreement =
      reference::solution_error(scene, check.radiosity, run.solve.radiosity);
  run.self_element_rms = agreement.element_rms;
  run.self_patch_rms = agreement.patch_rms;
  run.self_patch_max = agreement.patch_max;
  run.self_worst_patch = agreement.worst_patch;
  run.check_radiosity = check.radiosity;
  run.host_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  outputs.write("--out", reference::structure_text(scene, run));
  if (!mesh_path.empty()) outputs.write("--mesh", mesh_text(scene, run.solve.radiosity));
  outputs.commit();
  if (!quiet)
    std::printf("%s: the exact structure (%s): %zu elements, K = %d points a shooter (%lld rays), "
                "K/4 against K: element RMS %.3g, patch RMS %.3g; %d sweeps; %.1f s\n",
                scene.name.c_str(), reference::structure_name(structure).c_str(),
                scene.elements.size(), samples, run.stats.rays, run.self_element_rms,
                run.self_patch_rms, run.solve.sweeps, run.host_seconds);
  return kExitOk;
}
// ---- end of the exact structure's block

int run(int argc, char** argv) {
  CLI::App app{"The accuracy reference (docs/accuracy.md): element-to-element form factors "
               "integrated over both elements, solved to convergence.",
               "reference_solution"};
  std::string scene_name, out_path, mesh_path;
  int samples = 64, threads = 0, refine = 2;
  double part_size = 0.0;
  bool quiet = false;
  app.add_option("scene", scene_name, "scene file (JSON); a bare name is also looked up in scenes/")
      ->required();
  app.add_option("--samples", samples,
                 "K, points per element: the square of an even number from 4 to 1024 (16 or more "
                 "with --structure); the self-agreement is measured against K/4")
      ->capture_default_str();
  app.add_option("--refine", refine,
                 "solve on every element cut into N x N parts and give each element its parts' "
                 "area-weighted mean (1 to 4): the continuous radiosity's mean over the element, "
                 "not the element grid's own constant-radiosity answer (docs/accuracy.md)")
      ->capture_default_str();
  app.add_option("--part-size", part_size,
                 "also cut every element into parts no longer than this along either side (scene "
                 "units; at most 16 x 16 parts an element; 0: --refine alone): parts sized to the "
                 "furniture, so that a large element beside a small object does not send its "
                 "shadow's mean (docs/accuracy.md)")
      ->capture_default_str();
  app.add_option("--out", out_path, "write the reference solution (JSON) here")->required();
  app.add_option("--mesh", mesh_path,
                 "also write the reference as ./simulate's --mesh writes a solution (PLY: every "
                 "element a polygon, the picture's tone mapping, raw radiosity as doubles)");
  app.add_option("--threads", threads, "host threads (0: every core); the result does not depend on it")
      ->capture_default_str();
  app.add_flag("--quiet", quiet, "print nothing but errors");
  // The run's budget (issue 37, item 4; reference_budget.h): stated before it starts.
  double max_rays = reference::kDefaultMaxRays;
  app.add_option("--max-rays", max_rays,
                 "refuse (exit 2) a run whose rays, at most, exceed this (1 to 1e15; the "
                 "default 1e11 is about 4.5 hours of one thread)")
      ->capture_default_str();
  // ---- The exact structure's option (run_structure above)
  std::string structure_choice;
  app.add_option("--structure", structure_choice,
                 "instead of the reference, the exact solution of ./simulate's own structure "
                 "(receivers at element centres, shooters sending their elements' mean) with "
                 "exact form factors: patches (the paper's two levels) or elements (every "
                 "element its own patch); or the hemicube's own structure, point-to-element "
                 "factors from an eye on the shooter turned around by reciprocity: "
                 "hemicube-centre (one eye at the shooter's centroid) or hemicube-elements (an "
                 "eye at each shooter element's centroid); --samples is then K visibility "
                 "points a shooter (the hemicube's: a receiving element)")
      ->check(CLI::IsMember({"patches", "elements", "hemicube-centre", "hemicube-elements"}));
  // ---- end
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    std::cout << app.help();
    return kExitOk;
  } catch (const CLI::ParseError& e) {
    throw InputError(e.what());
  }
  const int side = int(std::lround(std::sqrt(double(samples))));
  if (side * side != samples || side % 2 != 0 || samples < 4 || samples > 1024)
    throw InputError("--samples " + std::to_string(samples) +
                     ": must be the square of an even number from 4 to 1024 (4, 16, 36, 64, ...)");
  // A structure is also solved at K/4 points (its self-agreement), and that needs a side of 2
  // at least: K = 4 would ask for one point (an internal error, exit 7, before this check).
  if (!structure_choice.empty() && samples < 16)
    throw InputError("--samples " + std::to_string(samples) +
                     " with --structure: its self-agreement solves at K/4 points, at least 4: "
                     "give 16 or more");
  // As ./simulate's --threads: more threads than cores gains nothing, and each takes a stack
  // (a huge count ended in SIGSEGV).
  if (threads < 0 || threads > 64)
    throw InputError("--threads " + std::to_string(threads) + ": must be 0 (every core) to 64");
  // The mesh is PLY whatever the name, as ./simulate's --mesh: a name promising another format
  // is refused.
  const std::string mesh_extension = std::filesystem::path(mesh_path).extension().string();
  if (!mesh_path.empty() && mesh_path != "-" && strcasecmp(mesh_extension.c_str(), ".ply") != 0 &&
      !mesh_extension.empty())
    throw InputError("--mesh " + mesh_path + ": only PLY is written (name it .ply)");
  if (refine < 1 || refine > 4)
    throw InputError("--refine " + std::to_string(refine) + ": must be 1, 2, 3 or 4");
  if (!(part_size >= 0.0 && part_size < 1e300))
    throw InputError("--part-size " + std::to_string(part_size) + ": must be 0 or a positive length");
  if (!(max_rays >= 1 && max_rays <= reference::kLargestMaxRays))
    throw InputError("--max-rays " + reference::budget_rays(max_rays) +
                     ": must be from 1 to 1e15");
  const std::string scene_file = resolve_scene(scene_name);
  const Scene scene = load_scene(scene_file);
  if (!structure_choice.empty()) {  // the exact structure's block (run_structure above)
    OutputFiles outputs({{"--out", out_path}, {"--mesh", mesh_path}}, {scene_file});
    reference::Structure structure = reference::Structure::kPatches;
    reference::structure_of(structure_choice, &structure);  // one of the names checked above
    return run_structure(scene, scene_file, structure, samples, threads, quiet, mesh_path, outputs);
  }
  // The scene solved: every patch's grid `refine` times finer (and, with --part-size, finer
  // still where an element is longer than that: cut_u, cut_v per patch). Its parts tile each
  // element exactly (grid_cell cuts the same bilinear map at finer parameters), in the scene's
  // element order: part (a, b) of element (i, j) is element (cut_u i + a, cut_v j + b) of the
  // fine grid.
  Scene fine = scene;
  std::vector<int> cut_u(scene.patches.size(), refine), cut_v(scene.patches.size(), refine);
  for (std::size_t p = 0; p < fine.patches.size(); ++p) {
    Patch& patch = fine.patches[p];
    if (part_size > 0.0) {
      // The element's longest side along each parameter: a quad's opposite edges, a triangle's
      // (v2 its collapsed far edge) edge v0 v1 and its two edges to v2.
      const Polygon& g = patch.polygon;
      const Vec3& far = g.count == 4 ? g[3] : g[2];
      const double along_u = std::max(glm::length(g[1] - g[0]), glm::length(g[2] - far)) / patch.nu;
      const double along_v = std::max(glm::length(far - g[0]), glm::length(g[2] - g[1])) / patch.nv;
      cut_u[p] = std::clamp(int(std::ceil(along_u / part_size - 1e-9)), refine, 16);
      cut_v[p] = std::clamp(int(std::ceil(along_v / part_size - 1e-9)), refine, 16);
    }
    patch.nu *= cut_u[p];
    patch.nv *= cut_v[p];
  }
  fine.build_elements();
  check_budget(fine, side, threads, max_rays, quiet);
  OutputFiles outputs({{"--out", out_path}, {"--mesh", mesh_path}}, {scene_file});

  const auto start = std::chrono::steady_clock::now();
  reference::ReferenceRun result;
  result.scene_file = fs::path(scene_file).filename().string();
  result.scene_sha256 = input_sha256(scene_file, kSceneFile);
  result.samples = samples;
  result.check_samples = samples / 4;
  result.refine = refine;
  result.part_size = part_size;
  const auto solve = [&](int point_side, reference::FormFactorStats& stats,
                         reference::SolveReport* report) {
    reference::FormFactorOptions options;
    options.side = point_side;
    options.threads = threads;
    std::vector<double> open;
    const reference::FormFactors factors = reference::area_form_factors(fine, options, &stats, &open);
    const std::vector<Rgb> parts = reference::element_means(
        fine, reference::solve_radiosity(fine, factors, 1e-13, 100000, report), open);
    std::vector<Rgb> means(scene.elements.size(), Rgb(0.0));
    std::vector<double> area(scene.elements.size(), 0.0);
    for (std::size_t p = 0; p < scene.patches.size(); ++p) {
      const Patch& coarse = scene.patches[p];
      const Patch& cut = fine.patches[p];
      for (int j = 0; j < cut.nv; ++j)
        for (int i = 0; i < cut.nu; ++i) {
          const std::size_t part = std::size_t(cut.first_element + j * cut.nu + i);
          const std::size_t element =
              std::size_t(coarse.first_element + (j / cut_v[p]) * coarse.nu + i / cut_u[p]);
          means[element] += fine.elements[part].area * parts[part];
          area[element] += fine.elements[part].area;
        }
    }
    for (std::size_t e = 0; e < means.size(); ++e) means[e] /= area[e];
    return means;
  };
  const std::vector<Rgb> check = solve(side / 2, result.check_stats, nullptr);
  result.radiosity = solve(side, result.stats, &result.solve);
  result.self_agreement = reference::solution_error(scene, check, result.radiosity);
  result.host_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  outputs.write("--out", reference::reference_text(scene, result));
  if (!mesh_path.empty()) outputs.write("--mesh", mesh_text(scene, result.radiosity));
  outputs.commit();
  if (!quiet)
    std::printf("%s: %zu elements, solved as %zu parts (--refine %d), K = %d points per part "
                "(%lld rays), K/4 = %d (%lld rays); "
                "K/4 against K: element RMS %.3g, patch RMS %.3g, largest patch %.3g; %.1f s\n",
                scene.name.c_str(), scene.elements.size(), fine.elements.size(), refine, samples,
                result.stats.rays,
                samples / 4, result.check_stats.rays, result.self_agreement.element_rms,
                result.self_agreement.patch_rms, result.self_agreement.patch_max,
                result.host_seconds);
  return kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
  return ncube::run_tool("reference_solution", [&] { return run(argc, argv); });
}

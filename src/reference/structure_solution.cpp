#include "reference/structure_solution.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <glm/geometric.hpp>

#include <nlohmann/json.hpp>

#include "reference/point_polygon_factor.h"
#include "reference/reference_file.h"
#include "reference/solution_error.h"
#include "util/version.h"
#include "reference/ray_visibility.h"
#include "reference/stratified_points.h"

namespace ncube::reference {
namespace {

constexpr int kPointsPerCellSide = 2;  // 2 x 2 jittered visibility points per cell
constexpr double kCoplanar = 1e-9;     // of the scene's diagonal: a point this close to a
                                       // parallel shooter's plane lies in it

// cos_x cos_y / r^2 times the point's weight: the kernel's relative weight of a point y of the
// shooter (normal ny) seen from x (normal nx); 0 where either faces away.
double kernel_weight(const Vec3& x, const Vec3& nx, const AreaSample& y, const Vec3& ny) {
  const Vec3 d = y.point - x;
  const double r2 = glm::dot(d, d);
  if (r2 <= 0.0) return 0.0;
  const double cos_x = glm::dot(nx, d);
  const double cos_y = -glm::dot(ny, d);
  if (cos_x <= 0.0 || cos_y <= 0.0) return 0.0;
  return y.weight * cos_x * cos_y / (r2 * r2);
}

bool some_corner_in_front(const Polygon& polygon, const Vec3& point, const Vec3& normal) {
  for (int c = 0; c < polygon.count; ++c)
    if (glm::dot(polygon[c] - point, normal) > 0.0) return true;
  return false;
}

}  // namespace

std::string structure_name(Structure structure) {
  switch (structure) {
    case Structure::kPatches: return "patches";
    case Structure::kElements: return "elements";
    case Structure::kHemicubeCentre: return "hemicube-centre";
    case Structure::kHemicubeElements: return "hemicube-elements";
  }
  return "";
}

bool structure_of(const std::string& name, Structure* structure) {
  for (Structure s : {Structure::kPatches, Structure::kElements, Structure::kHemicubeCentre,
                      Structure::kHemicubeElements})
    if (structure_name(s) == name) {
      *structure = s;
      return true;
    }
  return false;
}

Scene shooter_scene(const Scene& scene, Structure structure) {
  if (structure != Structure::kElements) return scene;
  Scene own;
  own.name = scene.name;
  own.camera = scene.camera;
  for (const Element& e : scene.elements) {
    Patch patch;
    patch.polygon = e.polygon;
    patch.reflectance = scene.patches[std::size_t(e.patch)].reflectance;
    patch.emission = scene.patches[std::size_t(e.patch)].emission;
    own.patches.push_back(patch);
  }
  own.build_elements();
  // The receiving point stays the element's centre as the scene's grid makes it.
  for (std::size_t e = 0; e < own.elements.size(); ++e) own.elements[e].centre = scene.elements[e].centre;
  return own;
}

StructureRows structure_form_factors(const Scene& shooters, const StructureOptions& options,
                                     StructureStats* stats) {
  if (options.side < 2 || options.side % 2 != 0)
    throw std::invalid_argument("structure_form_factors: side must be even and >= 2");
  const int cells = options.side / kPointsPerCellSide;  // g: cells on a side of a shooter
  const int n = int(shooters.elements.size());
  const int patches = int(shooters.patches.size());
  const RayVisibility rays(shooters);
  const double diagonal = scene_bounds(shooters).diagonal();
  std::vector<std::vector<Polygon>> cell_polygons(static_cast<std::size_t>(patches));
  for (int p = 0; p < patches; ++p)
    for (int j = 0; j < cells; ++j)
      for (int i = 0; i < cells; ++i)
        cell_polygons[std::size_t(p)].push_back(
            grid_cell(shooters.patches[std::size_t(p)].polygon, cells, cells, i, j));
  StructureRows rows(static_cast<std::size_t>(n));
  long long ray_total = 0, pair_total = 0;
  const int threads = options.threads > 0 ? options.threads : omp_get_num_procs();
#pragma omp parallel for schedule(dynamic, 4) num_threads(threads) reduction(+ : ray_total, pair_total)
  for (int e = 0; e < n; ++e) {
    const Element& receiver = shooters.elements[std::size_t(e)];
    const Vec3& x = receiver.centre;
    const Vec3& nx = shooters.patches[std::size_t(receiver.patch)].normal;
    for (int p = 0; p < patches; ++p) {
      if (p == receiver.patch) continue;  // an element does not receive its own patch's light
      const Patch& shooter = shooters.patches[std::size_t(p)];
      // One-sided: the shooter emits from its front only; and something of it must lie in
      // front of the receiver's tangent plane.
      const double height = glm::dot(shooter.normal, x - shooter.polygon[0]);
      if (height <= 0.0) continue;
      // In the shooter's plane (an element's neighbour on its patch when every element is a
      // patch, a decal on a wall): F = 0; rounding must not make it a pair.
      if (height <= kCoplanar * diagonal && glm::dot(shooter.normal, nx) > 1.0 - 1e-12) continue;
      if (!some_corner_in_front(shooter.polygon, x, nx)) continue;
      ++pair_total;
      double factor = 0.0;
      for (int c = 0; c < cells * cells; ++c) {
        const Polygon& cell = cell_polygons[std::size_t(p)][std::size_t(c)];
        const double unoccluded = point_polygon_factor(x, nx, cell);
        if (unoccluded <= 0.0) continue;
        const std::vector<AreaSample> points = stratified_points(
            cell, kPointsPerCellSide,
            mix_seed(options.seed, std::uint64_t(e), std::uint64_t(p) * std::uint64_t(cells * cells) + std::uint64_t(c)));
        double seen = 0.0, all = 0.0;
        for (const AreaSample& y : points) {
          const double weight = kernel_weight(x, nx, y, shooter.normal);
          if (weight <= 0.0) continue;
          all += weight;
          ++ray_total;
          if (rays.visible(x, nx, y.point, shooter.normal)) seen += weight;
        }
        // No point of the cell in front (a sliver seen edge-on): its tiny factor taken as seen.
        factor += unoccluded * (all > 0.0 ? seen / all : 1.0);
      }
      if (factor > 0.0) rows[std::size_t(e)].push_back({p, factor});
    }
  }
  if (stats) *stats = {ray_total, pair_total};
  return rows;
}

StructureRows eye_form_factors(const Scene& scene, Structure structure,
                               const StructureOptions& options, StructureStats* stats) {
  if (options.side < 2 || options.side % 2 != 0)
    throw std::invalid_argument("eye_form_factors: side must be even and >= 2");
  if (structure != Structure::kHemicubeCentre && structure != Structure::kHemicubeElements)
    throw std::invalid_argument("eye_form_factors: not a hemicube structure");
  const int cells = options.side / kPointsPerCellSide;  // g: cells on a side of a receiver
  const int n = int(scene.elements.size());
  const int patches = int(scene.patches.size());
  const RayVisibility rays(scene);
  // Every shooter's eyes: (point, area weight), as src/radiosity/hemicube.cpp places them
  // (the centroid of the patch, or of each cell of its nu x nv grid).
  struct Eye {
    Vec3 point;
    double area;
  };
  std::vector<std::vector<Eye>> eyes(static_cast<std::size_t>(patches));
  for (int p = 0; p < patches; ++p) {
    const Patch& shooter = scene.patches[std::size_t(p)];
    if (structure == Structure::kHemicubeCentre) {
      eyes[std::size_t(p)].push_back({shooter.polygon.centroid(), shooter.area});
    } else {
      for (int j = 0; j < shooter.nv; ++j)
        for (int i = 0; i < shooter.nu; ++i) {
          const Polygon element = grid_cell(shooter.polygon, shooter.nu, shooter.nv, i, j);
          eyes[std::size_t(p)].push_back({element.centroid(), element.area()});
        }
    }
  }
  StructureRows rows(static_cast<std::size_t>(n));
  long long ray_total = 0, pair_total = 0;
  const int threads = options.threads > 0 ? options.threads : omp_get_num_procs();
#pragma omp parallel for schedule(dynamic, 4) num_threads(threads) reduction(+ : ray_total, pair_total)
  for (int e = 0; e < n; ++e) {
    const Element& receiver = scene.elements[std::size_t(e)];
    const Vec3& ne = scene.patches[std::size_t(receiver.patch)].normal;
    std::vector<Polygon> receiver_cells;
    for (int j = 0; j < cells; ++j)
      for (int i = 0; i < cells; ++i) receiver_cells.push_back(grid_cell(receiver.polygon, cells, cells, i, j));
    for (int p = 0; p < patches; ++p) {
      if (p == receiver.patch) continue;  // the shooter's own elements lie in the eye's plane
      const Patch& shooter = scene.patches[std::size_t(p)];
      double sum = 0.0;  // sum over the eyes of A_eye F(eye -> e)
      for (std::size_t k = 0; k < eyes[std::size_t(p)].size(); ++k) {
        const Eye& eye = eyes[std::size_t(p)][k];
        // One-sided: the receiver receives on its front only (the hemicube gives a polygon
        // seen from behind nothing), and something of it must lie in front of the eye.
        if (glm::dot(ne, eye.point - receiver.polygon[0]) <= 0.0) continue;
        if (!some_corner_in_front(receiver.polygon, eye.point, shooter.normal)) continue;
        ++pair_total;
        double factor = 0.0;
        for (int c = 0; c < cells * cells; ++c) {
          const Polygon& cell = receiver_cells[std::size_t(c)];
          const double unoccluded = point_polygon_factor(eye.point, shooter.normal, cell);
          if (unoccluded <= 0.0) continue;
          const std::vector<AreaSample> points = stratified_points(
              cell, kPointsPerCellSide,
              mix_seed(options.seed, std::uint64_t(e),
                       (std::uint64_t(p) * 65536u + std::uint64_t(k)) * std::uint64_t(cells * cells) +
                           std::uint64_t(c)));
          double seen = 0.0, all = 0.0;
          for (const AreaSample& y : points) {
            // The kernel seen from the eye: the receiver's point y with normal ne.
            const double weight = kernel_weight(eye.point, shooter.normal, y, ne);
            if (weight <= 0.0) continue;
            all += weight;
            ++ray_total;
            if (rays.visible(eye.point, shooter.normal, y.point, ne)) seen += weight;
          }
          factor += unoccluded * (all > 0.0 ? seen / all : 1.0);
        }
        sum += eye.area * factor;
      }
      // Reciprocity, as the hemicube applies it: F(e -> p) = sum_eyes A_eye F(eye -> e) / A_e.
      if (sum > 0.0) rows[std::size_t(e)].push_back({p, sum / receiver.area});
    }
  }
  if (stats) *stats = {ray_total, pair_total};
  return rows;
}

StructureSolve solve_structure(const Scene& shooters, const StructureRows& rows, double tolerance,
                               int max_sweeps) {
  const std::size_t n = shooters.elements.size();
  StructureSolve out;
  out.radiosity.resize(n);
  std::vector<Rgb> mean(shooters.patches.size(), Rgb(0.0));  // Bbar_p
  for (std::size_t e = 0; e < n; ++e) {
    const Element& element = shooters.elements[e];
    const Patch& patch = shooters.patches[std::size_t(element.patch)];
    out.radiosity[e] = patch.emission;
    mean[std::size_t(element.patch)] += patch.emission * (element.area / patch.area);
  }
  while (out.sweeps < max_sweeps) {
    double change = 0.0, largest = 0.0;
    for (std::size_t e = 0; e < n; ++e) {
      const Element& element = shooters.elements[e];
      const Patch& patch = shooters.patches[std::size_t(element.patch)];
      Rgb gathered(0.0);
      for (const StructureEntry& entry : rows[e]) gathered += entry.value * mean[std::size_t(entry.shooter)];
      const Rgb next = patch.emission + patch.reflectance * gathered;
      change = std::max(change, std::fabs(luminance(next) - luminance(out.radiosity[e])));
      largest = std::max(largest, std::fabs(luminance(next)));
      mean[std::size_t(element.patch)] += (next - out.radiosity[e]) * (element.area / patch.area);
      out.radiosity[e] = next;
    }
    ++out.sweeps;
    out.last_change = largest > 0.0 ? change / largest : 0.0;
    if (out.last_change <= tolerance) break;
  }
  out.delivery.assign(shooters.patches.size(), 0.0);
  for (std::size_t e = 0; e < n; ++e)
    for (const StructureEntry& entry : rows[e])
      out.delivery[std::size_t(entry.shooter)] += shooters.elements[e].area * entry.value;
  for (std::size_t p = 0; p < out.delivery.size(); ++p) out.delivery[p] /= shooters.patches[p].area;
  return out;
}

}  // namespace ncube::reference

namespace ncube::reference {

std::string structure_text(const Scene& scene, const StructureRun& run) {
  nlohmann::json out;
  out["reference_file_version"] = kReferenceFileVersion;
  out["scene"] = scene.name;
  out["scene_file"] = run.scene_file;
  out["scene_sha256"] = run.scene_sha256;
  out["code_version"] = code_version();
  out["structure"] = structure_name(run.structure);
  out["method"] =
      run.structure == Structure::kPatches || run.structure == Structure::kElements
          ? "the exact solution of ./simulate's structure: every element receives at its "
            "centre, every " +
                std::string(run.structure == Structure::kPatches ? "patch" : "element (its own patch)") +
                " shoots its elements' area-weighted mean radiosity; F(centre -> shooter) = the "
                "shooter cut into cells, each cell's closed-form point-to-polygon factor "
                "(Lambert) times the kernel-weighted visible share of 2 x 2 jittered Embree "
                "rays; Gauss-Seidel to convergence (docs/accuracy.md)"
          : "the exact solution of the hemicube's structure (" +
                std::string(run.structure == Structure::kHemicubeCentre
                                ? "one eye at the shooter's centroid"
                                : "an eye at each shooter element's centroid, weighted by its area") +
                "): F(element -> shooter) = sum over the eyes of A_eye F(eye -> element) / "
                "A_element (reciprocity as the hemicube applies it, not clamped), F(eye -> "
                "element) = the element cut into cells, each cell's closed-form point-to-polygon "
                "factor (Lambert) times the kernel-weighted visible share of 2 x 2 jittered "
                "Embree rays from the eye; every patch shoots its elements' area-weighted mean "
                "radiosity; Gauss-Seidel to convergence (docs/accuracy.md)";
  out["samples"] = run.samples;
  out["check_samples"] = run.check_samples;
  out["self_agreement"] = {{"element_rms", run.self_element_rms},
                           {"patch_rms", run.self_patch_rms},
                           {"patch_max", run.self_patch_max},
                           {"worst_patch", run.self_worst_patch}};
  out["rays"] = run.stats.rays;
  out["check_rays"] = run.check_stats.rays;
  out["element_pairs"] = run.stats.pairs;
  out["solver_sweeps"] = run.solve.sweeps;
  out["solver_last_change"] = run.solve.last_change;
  out["host_seconds"] = run.host_seconds;
  out["element_count"] = scene.elements.size();
  out["patch_count"] = scene.patches.size();
  out["delivery"] = run.solve.delivery;
  out["element_columns"] = {"patch", "area", "radiosity_r", "radiosity_g", "radiosity_b"};
  std::string text = out.dump(1);
  text.erase(text.rfind('}'));
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  text += ",\n \"patch_luminance\": " + nlohmann::json(patch_luminances(scene, run.solve.radiosity)).dump();
  // The K/4 solution's element luminances: its self-agreement under any measure
  // (analysis/ncube/error_parts.py).
  std::vector<double> check(run.check_radiosity.size());
  for (std::size_t e = 0; e < check.size(); ++e) check[e] = luminance(run.check_radiosity[e]);
  text += ",\n \"check_luminance\": " + nlohmann::json(check).dump();
  text += ",\n \"elements\": [";
  for (std::size_t e = 0; e < scene.elements.size(); ++e) {
    const Rgb& b = run.solve.radiosity[e];
    text += (e ? ",\n  " : "\n  ") +
            nlohmann::json({scene.elements[e].patch, scene.elements[e].area, b.r, b.g, b.b}).dump();
  }
  text += "\n ]";
  if (run.structure == Structure::kHemicubeCentre || run.structure == Structure::kHemicubeElements) {
    // Where reciprocity gave a factor above 1: [element, shooter, F(element -> shooter)].
    text += ",\n \"above_one_columns\": [\"element\", \"shooter\", \"factor\"],\n \"above_one\": [";
    for (std::size_t k = 0; k < run.above_one.size(); ++k)
      text += (k ? ",\n  " : "\n  ") +
              nlohmann::json({run.above_one[k].first, run.above_one[k].second.shooter,
                              run.above_one[k].second.value}).dump();
    text += "\n ]";
  }
  text += "\n}\n";
  return text;
}

std::vector<std::pair<int, StructureEntry>> entries_above_one(const StructureRows& rows) {
  std::vector<std::pair<int, StructureEntry>> out;
  for (std::size_t e = 0; e < rows.size(); ++e)
    for (const StructureEntry& entry : rows[e])
      if (entry.value > 1.0) out.push_back({int(e), entry});
  return out;
}

}  // namespace ncube::reference

#include "reference/reference_file.h"

#include "util/version.h"

namespace ncube::reference {

std::string reference_text(const Scene& scene, const ReferenceRun& run) {
  nlohmann::json out;
  out["reference_file_version"] = kReferenceFileVersion;
  out["scene"] = scene.name;
  out["scene_file"] = run.scene_file;
  out["scene_sha256"] = run.scene_sha256;
  out["code_version"] = code_version();
  out["method"] =
      "every element solved as refine x refine parts, its radiosity their area-weighted mean; "
      "part-to-part form factors integrated over both parts: K jittered points per part "
      "(an enclosed part, seeing only backs, sends nothing); far pairs: cos cos / (pi r^2) at K point pairs, an Embree visibility ray each; "
      "near pairs: the inner integral in closed form (Lambert's contour integral) times the "
      "kernel-weighted visible share of K x K rays; Gauss-Seidel to convergence "
      "(docs/accuracy.md)";
  out["refine"] = run.refine;
  if (run.part_size > 0.0) out["part_size"] = run.part_size;
  out["samples"] = run.samples;
  out["check_samples"] = run.check_samples;
  out["self_agreement"] = {{"element_rms", run.self_agreement.element_rms},
                           {"patch_rms", run.self_agreement.patch_rms},
                           {"patch_max", run.self_agreement.patch_max},
                           {"worst_patch", run.self_agreement.worst_patch}};
  out["rays"] = run.stats.rays;
  out["check_rays"] = run.check_stats.rays;
  out["element_pairs"] = run.stats.pairs;
  out["near_pairs"] = run.stats.near_pairs;
  out["solver_sweeps"] = run.solve.sweeps;
  out["solver_last_change"] = run.solve.last_change;
  out["host_seconds"] = run.host_seconds;
  out["element_count"] = scene.elements.size();
  out["patch_count"] = scene.patches.size();
  out["element_columns"] = {"patch", "area", "radiosity_r", "radiosity_g", "radiosity_b"};
  // One element a line: [patch, area, r, g, b], numbers as nlohmann writes them (they read
  // back to the same doubles).
  std::string text = out.dump(1);
  text.erase(text.rfind('}'));
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  text += ",\n \"patch_luminance\": " + nlohmann::json(patch_luminances(scene, run.radiosity)).dump();
  text += ",\n \"elements\": [";
  for (std::size_t e = 0; e < scene.elements.size(); ++e) {
    const Rgb& b = run.radiosity[e];
    text += (e ? ",\n  " : "\n  ") +
            nlohmann::json({scene.elements[e].patch, scene.elements[e].area, b.r, b.g, b.b}).dump();
  }
  text += "\n ]\n}\n";
  return text;
}

}  // namespace ncube::reference

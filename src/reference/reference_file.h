// The reference solution's file (docs/accuracy.md, "The file"): JSON with the scene's
// identity, the method and its sample counts, the self-agreement of two sample counts, the
// cost, each patch's luminance, and every element's [patch, area, r, g, b] in the scene's
// element order (the order of ./simulate's --mesh faces without --subdivide), one a line.
// Deterministic apart from host_seconds and code_version.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "reference/area_form_factors.h"
#include "reference/radiosity_solve.h"
#include "reference/solution_error.h"
#include "scene/scene.h"

namespace ncube::reference {

constexpr int kReferenceFileVersion = 1;  // the layout; "refine" (issue 38) was added to it

struct ReferenceRun {
  std::string scene_file, scene_sha256;
  int samples = 0, check_samples = 0;
  int refine = 1;  // every element solved as refine x refine parts
  double part_size = 0.0;  // and finer where an element is longer (0: refine alone); in the
                           // file only when set, so files made without it keep their bytes
  FormFactorStats stats, check_stats;
  SolveReport solve;
  SolutionError self_agreement;  // the check_samples solution against the samples one
  double host_seconds = 0.0;
  std::vector<Rgb> radiosity;
};

std::string reference_text(const Scene& scene, const ReferenceRun& run);

}  // namespace ncube::reference

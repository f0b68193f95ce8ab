// How far one element solution lies from another (docs/accuracy.md), the measure
// analysis/ncube/accuracy.py applies to ./simulate's meshes, here for the reference's own
// self-agreement (K against 4K points per element). Luminance is Rec. 709's (scene.h).
//  - element: the area-weighted RMS of the relative errors r_e = (Y_e - Yref_e) / Yref_e,
//    sqrt(sum A_e r_e^2 / sum A_e) over the elements with Yref_e > 0 (normalising by the
//    reference's RMS instead would let the light, 100 times brighter than the walls and
//    exact, hide every other error);
//  - patch: a patch's luminance is the area-weighted mean of its elements'; the largest
//    |Y_p - Yref_p| / Yref_p over patches with Yref_p > 0, and their area-weighted RMS.
#pragma once

#include <vector>

#include "scene/scene.h"

namespace ncube::reference {

struct SolutionError {
  double element_rms = 0.0;
  double patch_rms = 0.0;
  double patch_max = 0.0;
  int worst_patch = -1;
};

SolutionError solution_error(const Scene& scene, const std::vector<Rgb>& solution,
                             const std::vector<Rgb>& reference);

// Each patch's luminance: the area-weighted mean of its elements'.
std::vector<double> patch_luminances(const Scene& scene, const std::vector<Rgb>& elements);

}  // namespace ncube::reference

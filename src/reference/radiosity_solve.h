// The reference's radiosity: B_i = E_i + rho_i sum_j F_ij B_j on the scene's elements, all
// three colours at once, by Gauss-Seidel sweeps to convergence (every element, not the
// simulator's patch-level shooting: the element-level answer the discretisation allows).
#pragma once

#include <vector>

#include "reference/area_form_factors.h"
#include "scene/scene.h"

namespace ncube::reference {

struct SolveReport {
  int sweeps = 0;
  double last_change = 0.0;  // largest change of an element's luminance in the last sweep,
                             // relative to the largest luminance
};

// Stops when a sweep changes no element's luminance by more than `tolerance` of the largest
// (or after max_sweeps). Elements' emission and reflectance are their patch's. Each pair is
// held once (FormFactors): element i gathers from j < i what those, once updated in the
// sweep, scattered into it, then from j > i along its own row; the same sums in the same
// order as rows held both ways, so the same answer to the last bit.
std::vector<Rgb> solve_radiosity(const Scene& scene, const FormFactors& factors,
                                 double tolerance = 1e-13, int max_sweeps = 100000,
                                 SolveReport* report = nullptr);

// Each element's mean radiosity over its whole area from the radiosity of its open part
// (area_form_factors.h): open_i B_i + (1 - open_i) E_i, the enclosed part receiving nothing.
std::vector<Rgb> element_means(const Scene& scene, const std::vector<Rgb>& open_radiosity,
                               const std::vector<double>& open_fraction);

}  // namespace ncube::reference

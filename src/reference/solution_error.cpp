#include "reference/solution_error.h"

#include <cmath>

namespace ncube::reference {

std::vector<double> patch_luminances(const Scene& scene, const std::vector<Rgb>& elements) {
  std::vector<double> sum(scene.patches.size(), 0.0), area(scene.patches.size(), 0.0);
  for (std::size_t e = 0; e < scene.elements.size(); ++e) {
    const std::size_t p = std::size_t(scene.elements[e].patch);
    sum[p] += scene.elements[e].area * luminance(elements[e]);
    area[p] += scene.elements[e].area;
  }
  for (std::size_t p = 0; p < sum.size(); ++p) sum[p] = area[p] > 0.0 ? sum[p] / area[p] : 0.0;
  return sum;
}

SolutionError solution_error(const Scene& scene, const std::vector<Rgb>& solution,
                             const std::vector<Rgb>& reference) {
  SolutionError out;
  double squares = 0.0, area = 0.0;
  for (std::size_t e = 0; e < scene.elements.size(); ++e) {
    const double y_ref = luminance(reference[e]);
    if (y_ref <= 0.0) continue;
    const double relative = (luminance(solution[e]) - y_ref) / y_ref;
    squares += scene.elements[e].area * relative * relative;
    area += scene.elements[e].area;
  }
  out.element_rms = area > 0.0 ? std::sqrt(squares / area) : 0.0;
  const std::vector<double> y = patch_luminances(scene, solution);
  const std::vector<double> y_ref = patch_luminances(scene, reference);
  double patch_squares = 0.0, patch_area = 0.0;
  for (std::size_t p = 0; p < y.size(); ++p) {
    if (y_ref[p] <= 0.0) continue;
    const double relative = std::fabs(y[p] - y_ref[p]) / y_ref[p];
    patch_squares += scene.patches[p].area * relative * relative;
    patch_area += scene.patches[p].area;
    if (relative > out.patch_max || out.worst_patch < 0) {
      out.patch_max = relative;
      out.worst_patch = int(p);
    }
  }
  out.patch_rms = patch_area > 0.0 ? std::sqrt(patch_squares / patch_area) : 0.0;
  return out;
}

}  // namespace ncube::reference

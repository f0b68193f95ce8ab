#include "reference/radiosity_solve.h"

#include <algorithm>
#include <cmath>

namespace ncube::reference {

std::vector<Rgb> solve_radiosity(const Scene& scene, const FormFactorRows& rows, double tolerance,
                                 int max_sweeps, SolveReport* report) {
  const std::size_t n = scene.elements.size();
  std::vector<Rgb> b(n);
  for (std::size_t i = 0; i < n; ++i) b[i] = scene.patches[std::size_t(scene.elements[i].patch)].emission;
  SolveReport done;
  while (done.sweeps < max_sweeps) {
    double change = 0.0, largest = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const Patch& patch = scene.patches[std::size_t(scene.elements[i].patch)];
      Rgb gathered(0.0);
      for (const FormFactorEntry& e : rows[i]) gathered += e.value * b[std::size_t(e.element)];
      const Rgb next = patch.emission + patch.reflectance * gathered;
      change = std::max(change, std::fabs(luminance(next) - luminance(b[i])));
      largest = std::max(largest, std::fabs(luminance(next)));
      b[i] = next;
    }
    ++done.sweeps;
    done.last_change = largest > 0.0 ? change / largest : 0.0;
    if (done.last_change <= tolerance) break;
  }
  if (report) *report = done;
  return b;
}

std::vector<Rgb> element_means(const Scene& scene, const std::vector<Rgb>& open_radiosity,
                               const std::vector<double>& open_fraction) {
  std::vector<Rgb> mean(open_radiosity.size());
  for (std::size_t i = 0; i < mean.size(); ++i) {
    const Rgb& emission = scene.patches[std::size_t(scene.elements[i].patch)].emission;
    mean[i] = open_fraction[i] * open_radiosity[i] + (1.0 - open_fraction[i]) * emission;
  }
  return mean;
}

}  // namespace ncube::reference

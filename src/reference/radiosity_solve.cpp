#include "reference/radiosity_solve.h"

#include <algorithm>
#include <cmath>

namespace ncube::reference {

std::vector<Rgb> solve_radiosity(const Scene& scene, const FormFactors& factors, double tolerance,
                                 int max_sweeps, SolveReport* report) {
  const std::size_t n = scene.elements.size();
  // lower[i]: sum over j < i of F_ij B_j, from the B_j of this sweep, j ascending.
  std::vector<Rgb> lower(n);
  std::vector<Rgb> b(n);
  for (std::size_t i = 0; i < n; ++i) b[i] = scene.patches[std::size_t(scene.elements[i].patch)].emission;
  SolveReport done;
  while (done.sweeps < max_sweeps) {
    double change = 0.0, largest = 0.0;
    std::fill(lower.begin(), lower.end(), Rgb(0.0));
    for (std::size_t i = 0; i < n; ++i) {
      const Patch& patch = scene.patches[std::size_t(scene.elements[i].patch)];
      const FormFactors::Row& row = factors.upper(int(i));
      const double open_i = factors.open_area(int(i));
      Rgb gathered = lower[i];
      if (open_i > 0.0)
        for (std::size_t k = 0; k < row.column.size(); ++k)
          gathered += (row.exchange[k] / open_i) * b[std::size_t(row.column[k])];
      const Rgb next = patch.emission + patch.reflectance * gathered;
      change = std::max(change, std::fabs(luminance(next) - luminance(b[i])));
      largest = std::max(largest, std::fabs(luminance(next)));
      b[i] = next;
      for (std::size_t k = 0; k < row.column.size(); ++k) {
        const std::size_t j = std::size_t(row.column[k]);
        const double open_j = factors.open_area(int(j));
        if (open_j > 0.0) lower[j] += (row.exchange[k] / open_j) * next;
      }
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

#include "machine/rate_fit.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace ncube {

RateFit fit_seconds_per_flop(const std::vector<TimedRun>& runs) {
  if (runs.empty()) throw std::invalid_argument("rate fit: no runs");
  const std::size_t kinds = runs[0].flops.size(), n = runs.size();
  if (kinds == 0) throw std::invalid_argument("rate fit: no kinds of work");
  if (n < kinds)
    throw std::invalid_argument("rate fit: " + std::to_string(n) + " runs for " +
                                std::to_string(kinds) + " kinds of work");
  // a[i][k] = flops of kind k in run i / its seconds; the right-hand side is 1 for every run.
  std::vector<std::vector<double>> a(n, std::vector<double>(kinds));
  std::vector<double> b(n, 1.0);
  for (std::size_t i = 0; i < n; ++i) {
    if (runs[i].flops.size() != kinds)
      throw std::invalid_argument("rate fit: run " + std::to_string(i) + " has " +
                                  std::to_string(runs[i].flops.size()) + " kinds, not " +
                                  std::to_string(kinds));
    if (!(runs[i].seconds > 0) || !std::isfinite(runs[i].seconds))
      throw std::invalid_argument("rate fit: run " + std::to_string(i) + " took no time");
    for (std::size_t k = 0; k < kinds; ++k) a[i][k] = runs[i].flops[k] / runs[i].seconds;
  }
  // Columns scaled to unit length, so that a kind of 1e9 flops and one of 1e6 weigh alike in
  // the factorisation's pivots.
  std::vector<double> scale(kinds);
  for (std::size_t k = 0; k < kinds; ++k) {
    double sum = 0;
    for (std::size_t i = 0; i < n; ++i) sum += a[i][k] * a[i][k];
    if (!(sum > 0)) throw std::invalid_argument("rate fit: kind " + std::to_string(k) +
                                                " has no flops in any run");
    scale[k] = std::sqrt(sum);
    for (std::size_t i = 0; i < n; ++i) a[i][k] /= scale[k];
  }
  // Householder QR: R overwrites a's upper triangle, Q^T b overwrites b.
  for (std::size_t k = 0; k < kinds; ++k) {
    double norm = 0;
    for (std::size_t i = k; i < n; ++i) norm += a[i][k] * a[i][k];
    norm = std::sqrt(norm);
    // A column that is (nearly) a combination of the ones before it: no mix separates them.
    if (norm < 1e-10) throw std::invalid_argument("rate fit: the kinds' flops are linearly "
                                                  "dependent over the runs");
    const double alpha = a[k][k] > 0 ? -norm : norm;
    std::vector<double> v(n, 0.0);
    for (std::size_t i = k; i < n; ++i) v[i] = a[i][k];
    v[k] -= alpha;
    double vv = 0;
    for (std::size_t i = k; i < n; ++i) vv += v[i] * v[i];
    for (std::size_t j = k; j < kinds; ++j) {
      double dot = 0;
      for (std::size_t i = k; i < n; ++i) dot += v[i] * a[i][j];
      for (std::size_t i = k; i < n; ++i) a[i][j] -= 2 * dot / vv * v[i];
    }
    double dot = 0;
    for (std::size_t i = k; i < n; ++i) dot += v[i] * b[i];
    for (std::size_t i = k; i < n; ++i) b[i] -= 2 * dot / vv * v[i];
  }
  RateFit fit;
  fit.seconds_per_flop.assign(kinds, 0.0);
  for (std::size_t k = kinds; k-- > 0;) {
    double sum = b[k];
    for (std::size_t j = k + 1; j < kinds; ++j) sum -= a[k][j] * fit.seconds_per_flop[j];
    fit.seconds_per_flop[k] = sum / a[k][k];
  }
  for (std::size_t k = 0; k < kinds; ++k) fit.seconds_per_flop[k] /= scale[k];
  double squares = 0;
  for (const TimedRun& run : runs) {
    double fitted = 0;
    for (std::size_t k = 0; k < kinds; ++k) fitted += run.flops[k] * fit.seconds_per_flop[k];
    const double residual = (fitted - run.seconds) / run.seconds;
    fit.relative_residuals.push_back(residual);
    squares += residual * residual;
  }
  fit.rms_relative_residual = std::sqrt(squares / double(n));
  return fit;
}

}  // namespace ncube

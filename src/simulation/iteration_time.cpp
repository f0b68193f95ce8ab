#include "simulation/iteration_time.h"

#include <algorithm>
#include <numeric>

namespace ncube {

int iterations_measured(const std::vector<double>& iteration_seconds) {
  return std::min(int(iteration_seconds.size()), kIterationsPerMeasure);
}

std::optional<double> seconds_per_iteration(const std::vector<double>& iteration_seconds) {
  const int n = iterations_measured(iteration_seconds);
  if (n == 0) return std::nullopt;
  return std::accumulate(iteration_seconds.begin(), iteration_seconds.begin() + n, 0.0) / n;
}

}  // namespace ncube

// The one definition of "seconds per iteration" (docs/reproduce.md): the mean simulated time
// of the first 20 iterations, measured at the master, or of all of them when fewer ran. The
// summary of ./simulate, the result file, the sweeps and the report all use this figure.
// Why 20: early iterations shoot the lights, later ones lit surfaces that send less light to
// fewer receivers; 20 cover all lights of scenes 0 to 2 and most of scene3's 24, which is
// what the paper's "time for one iteration" is compared with.
#pragma once

#include <optional>
#include <vector>

namespace ncube {

constexpr int kIterationsPerMeasure = 20;

// The measure over `iteration_seconds` (one entry per iteration); none without iterations.
std::optional<double> seconds_per_iteration(const std::vector<double>& iteration_seconds);

// How many iterations the measure averages: min(20, iterations run).
int iterations_measured(const std::vector<double>& iteration_seconds);

}  // namespace ncube

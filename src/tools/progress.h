// Progress of a long run on stderr (when it is a terminal; --quiet silences it): the
// iteration, the largest unshot power against the convergence threshold, the simulated time
// and an estimate of the host time left. Silent for the first two seconds, so that short runs
// print only their summary.
#pragma once

#include <chrono>
#include <cstdio>
#include <vector>

#include "simulation/simulation.h"

namespace ncube {

class Progress {
 public:
  // max_iterations < 0: until converged (the time left is extrapolated from how fast the
  // largest unshot power has been falling).
  Progress(std::FILE* stream, int max_iterations);
  ~Progress();  // ends the progress line

  void report(const IterationReport& report);

  // The estimate alone, for tests: iterations still to go, or a negative value when unknown.
  static double iterations_left(const std::vector<double>& log_powers, double log_threshold,
                                int iterations_done, int max_iterations);

 private:
  std::FILE* stream_;
  int max_iterations_;
  std::chrono::steady_clock::time_point start_, last_print_;
  std::vector<double> log_powers_;
  bool printed_ = false;
};

// Whether stderr is a terminal.
bool stderr_is_terminal();

}  // namespace ncube

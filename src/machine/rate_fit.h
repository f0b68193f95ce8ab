// Rates per kind of work fitted to timed runs of counted kernels (build/machine_probe): a run
// that did flops f_k of each kind k in t seconds says t = sum_k f_k / rate_k; over several runs
// with different mixes of the kinds, the seconds a flop of each kind (1 / rate_k) are the least
// squares solution. Relative least squares (each run's equation divided by its own t), a
// choice: the simulator is held to a relative error, so a short run's miss counts as much as a
// long run's (docs/machines/probe.md, "The probe").
#pragma once

#include <vector>

namespace ncube {

struct TimedRun {
  std::vector<double> flops;  // counted flops of each kind, in the fit's order of kinds
  double seconds = 0;         // the time measured for them (> 0)
};

struct RateFit {
  std::vector<double> seconds_per_flop;  // of each kind, in the runs' order of kinds
  // Each run's (fitted seconds - measured seconds) / measured seconds, in the runs' order.
  std::vector<double> relative_residuals;
  double rms_relative_residual = 0;      // their root mean square
};

// The relative least squares fit of seconds = sum_k flops_k x_k over `runs` (Householder QR on
// the scaled columns). std::invalid_argument when there are fewer runs than kinds, the runs
// differ in their number of kinds, a time is not positive, or the kinds' flops are linearly
// dependent over the runs (no mix tells them apart). The seconds a flop may come out zero or
// negative on noisy runs: the caller decides what that means.
RateFit fit_seconds_per_flop(const std::vector<TimedRun>& runs);

}  // namespace ncube

#include "tools/progress.h"

#include <algorithm>
#include <cmath>
#include <unistd.h>

namespace ncube {
namespace {

constexpr double kSilentSeconds = 2.0;   // runs shorter than this print no progress
constexpr double kPrintInterval = 0.25;  // seconds between two updates of the line
constexpr int kTrendIterations = 50;     // iterations the decay of the unshot power is fitted on

double seconds_between(std::chrono::steady_clock::time_point a, std::chrono::steady_clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

}  // namespace

bool stderr_is_terminal() { return isatty(STDERR_FILENO) != 0; }

Progress::Progress(std::FILE* stream, int max_iterations)
    : stream_(stream), max_iterations_(max_iterations),
      start_(std::chrono::steady_clock::now()), last_print_(start_) {}

Progress::~Progress() {
  if (printed_) std::fprintf(stream_, "\n");
}

double Progress::iterations_left(const std::vector<double>& log_powers, double log_threshold,
                                 int iterations_done, int max_iterations) {
  double left = max_iterations >= 0 ? double(max_iterations - iterations_done) : -1.0;
  // The largest unshot power falls roughly geometrically: extrapolate its recent trend.
  const int n = int(log_powers.size());
  const int k = std::min(n - 1, kTrendIterations);
  if (k >= 2) {
    const double rate = (log_powers[n - 1] - log_powers[n - 1 - k]) / k;
    if (rate < 0) {
      const double to_threshold = std::max(0.0, (log_threshold - log_powers[n - 1]) / rate);
      left = left < 0 ? to_threshold : std::min(left, to_threshold);
    }
  }
  return left;
}

void Progress::report(const IterationReport& r) {
  if (r.largest_unshot_power > 0) log_powers_.push_back(std::log(r.largest_unshot_power));
  const auto now = std::chrono::steady_clock::now();
  const double elapsed = seconds_between(start_, now);
  if (elapsed < kSilentSeconds || seconds_between(last_print_, now) < kPrintInterval) return;
  last_print_ = now;
  const double left = iterations_left(log_powers_, std::log(r.threshold_power), r.iterations_done,
                                      max_iterations_);
  char estimate[64] = "host time left unknown";
  if (left >= 0 && r.iterations_done > 0)
    std::snprintf(estimate, sizeof estimate, "about %.0f s of host time left",
                  elapsed / r.iterations_done * left);
  std::fprintf(stream_, "\riteration %d%s%s  unshot %.3g (threshold %.3g)  simulated %.1f s  %s   ",
               r.iterations_done, max_iterations_ >= 0 ? " of " : "",
               max_iterations_ >= 0 ? std::to_string(max_iterations_).c_str() : "",
               r.largest_unshot_power, r.threshold_power, r.simulated_seconds, estimate);
  std::fflush(stream_);
  printed_ = true;
}

}  // namespace ncube

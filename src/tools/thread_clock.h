#pragma once
// The probe's clock and summary, shared by build/machine_probe's rates and its --scenes timing
// (docs/machines/probe.md): the thread's CPU time, so that a shared host's other processes do
// not count, and the median of a run's repeats.

#include <algorithm>
#include <ctime>
#include <vector>

namespace ncube {

inline double thread_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

inline double median(std::vector<double> s) {
  std::sort(s.begin(), s.end());
  const std::size_t n = s.size();
  return n % 2 ? s[n / 2] : 0.5 * (s[n / 2 - 1] + s[n / 2]);
}

}  // namespace ncube

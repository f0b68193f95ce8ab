#include "reference/reference_budget.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <vector>

#include <glm/geometric.hpp>

#include "reference/area_form_factors.h"
#include "util/input_error.h"
#include "util/input_file.h"

namespace ncube::reference {

long long pairs_of(const Scene& fine) {
  const long long n = static_cast<long long>(fine.elements.size());
  long long same_patch = 0;
  for (const Patch& patch : fine.patches) {
    const long long m = static_cast<long long>(patch.nu) * patch.nv;
    same_patch += m * (m - 1) / 2;
  }
  return n * (n - 1) / 2 - same_patch;
}

ReferenceBudget reference_budget(const Scene& fine, int side) {
  ReferenceBudget budget;
  const std::size_t n = fine.elements.size();
  budget.parts = static_cast<long long>(n);
  budget.pairs = pairs_of(fine);
  // The near test of area_form_factors.cpp: centres closer than kNearFactor times the sum of
  // the two elements' radii (a radius: the farthest corner from the centre).
  std::vector<double> radius(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const Element& e = fine.elements[i];
    for (int c = 0; c < e.polygon.count; ++c)
      radius[i] = std::max(radius[i], glm::length(e.polygon[c] - e.centre));
  }
  const double factor = FormFactorOptions::kNearFactor;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      if (fine.elements[j].patch == fine.elements[i].patch) continue;
      const Vec3 d = fine.elements[j].centre - fine.elements[i].centre;
      const double reach = factor * (radius[i] + radius[j]);
      if (glm::dot(d, d) < reach * reach) ++budget.near_pairs;
    }
  const double far = double(budget.pairs - budget.near_pairs);
  for (const int s : {side, side / 2}) {
    const double k = double(s) * s;
    budget.rays += far * k + double(budget.near_pairs) * k * k;
  }
  budget.bytes = double(budget.pairs) * kBytesPerPair + double(n) * side * side * kBytesPerPoint;
  budget.host_seconds = budget.rays * kSecondsPerRay + 2.0 * double(budget.pairs) * kSecondsPerPair;
  return budget;
}

double host_memory_available() {
  double available = std::numeric_limits<double>::max();
  try {
    std::istringstream meminfo(read_input_file("/proc/meminfo", kKernelFile));
    std::string line;
    while (std::getline(meminfo, line))
      if (line.rfind("MemAvailable:", 0) == 0) {
        std::istringstream fields(line.substr(13));
        double kib = 0.0;
        if (fields >> kib) available = kib * 1024.0;
      }
    rlimit limit{};
    if (getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY) {
      std::istringstream statm(read_input_file("/proc/self/statm", kKernelFile));
      double mapped = 0.0;
      if (statm >> mapped) mapped *= double(sysconf(_SC_PAGESIZE));
      available = std::min(available, std::max(0.0, double(limit.rlim_cur) - mapped));
    }
  } catch (const InputError&) {
    // No /proc: nothing known, the run tries (and a bad_alloc is exit 6).
  }
  return available;
}

std::string budget_bytes(double bytes) {
  char text[32];
  if (bytes >= 1e9)
    std::snprintf(text, sizeof text, "%.1f GB", bytes / 1e9);
  else
    std::snprintf(text, sizeof text, "%.0f MB", std::ceil(bytes / 1e6));
  return text;
}

std::string budget_rays(double rays) {
  char text[32];
  std::snprintf(text, sizeof text, rays < 1e6 ? "%.0f" : "%.2g", rays);
  return text;
}

std::string budget_time(double seconds) {
  char text[48];
  if (seconds < 90)
    std::snprintf(text, sizeof text, "%.0f s", std::ceil(seconds));
  else if (seconds < 5400)
    std::snprintf(text, sizeof text, "%.0f min", std::ceil(seconds / 60));
  else if (seconds < 3 * 86400)
    std::snprintf(text, sizeof text, "%.1f h", seconds / 3600);
  else
    std::snprintf(text, sizeof text, "%.0f days", seconds / 86400);
  return text;
}

}  // namespace ncube::reference

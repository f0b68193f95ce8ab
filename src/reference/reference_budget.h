// What a reference run (build/reference_solution) will take, worked out from the scene before
// anything is integrated (issue 37, item 4): its rays, its memory and a rough host time, so
// that a large K on many elements is stated first and refused beyond documented limits
// (docs/accuracy.md, "The command"), instead of running for days or into the host's memory.
// Every figure is an upper bound of what area_form_factors.h does, or as said a rough rate.
#pragma once

#include <cstdint>
#include <string>

#include "scene/scene.h"

namespace ncube::reference {

struct ReferenceBudget {
  long long parts = 0;       // the elements solved (the scene's elements cut --refine times)
  long long pairs = 0;       // unordered part pairs on different patches (those tested)
  long long near_pairs = 0;  // of them near (FormFactorOptions::kNearFactor): K x K rays each
  double rays = 0.0;         // at most, both solves (K and K/4 points per part)
  double bytes = 0.0;        // peak host memory of the form factors, about (at most)
  double host_seconds = 0.0; // rough, on one thread (the rates below)
};

// Rough costs per thread, measured on the development machine (cornell-box, --refine 1 at
// K = 64 and --refine 2 at K = 4, loaded 2-core host): one visibility ray, one pair of parts
// (its tests, points and permutation). A pair kept is held once (FormFactors in
// area_form_factors.h): a 32-bit index and a double, rows at their exact size; at most every
// pair is kept.
constexpr double kSecondsPerRay = 0.16e-6;
constexpr double kSecondsPerPair = 0.8e-6;
constexpr double kBytesPerPair = 12.0;
constexpr double kBytesPerPoint = 32.0;  // an AreaSample

// The default and largest of --max-rays: the default about 4.5 hours of one thread at
// kSecondsPerRay; a larger budget is the user's explicit choice.
constexpr double kDefaultMaxRays = 1e11;
constexpr double kLargestMaxRays = 1e15;

// The budget of solving `fine` (the scene already cut into its parts, elements built) at
// side x side points per part and at (side/2)^2 for the self-agreement. The near pairs are
// counted by the distance test alone (the facing tests only remove pairs), in O(parts^2)
// cheap tests: call only when `pairs_of(fine)` fits in memory.
ReferenceBudget reference_budget(const Scene& fine, int side);

// The unordered pairs of elements on different patches, from the patches' element counts.
long long pairs_of(const Scene& fine);

// The host memory a process may still take: the smaller of MemAvailable (/proc/meminfo) and
// the address-space limit (ulimit -v) less what is mapped now; a very large number when
// neither is known.
double host_memory_available();

// "1.5 GB", "3.2e10", "2 h 5 min": the figures as the estimate line prints them.
std::string budget_bytes(double bytes);
std::string budget_rays(double rays);
std::string budget_time(double seconds);

}  // namespace ncube::reference

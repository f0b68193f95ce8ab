// The picture's exposure: the 95th percentile of the luminance of the visible non-emitting
// samples (of all visible samples when no non-emitter shows) maps to 0.9. Shared by the
// sequential render, which sorts its samples, and the parallel one (paper section 2.3),
// which selects the same sample's value with a radix select over the nodes' histograms, so
// that both pictures are identical.
#pragma once

#include <cstdint>
#include <vector>

#include "scene/scene.h"

namespace ncube {


// The sRGB encoding of a linear value in [0, 1] (the picture's, and the solution mesh's
// vertex colours).
double srgb_encode(double linear);

// The order statistic the exposure uses, over one set of luminances.
struct LuminanceSelection {
  std::uint64_t count = 0;  // values in the set
  double kth = 0.0;         // the value of rank percentile_rank(count) (0-based, ascending)
  double max = 0.0;         // the largest value
};

// The rank of the 95th percentile among `count` values: floor(0.95 (count - 1)).
std::uint64_t percentile_rank(std::uint64_t count);

// Exposure scale from the non-emitters' and all visible samples' selections.
double exposure_scale(const LuminanceSelection& non_emitters, const LuminanceSelection& all);

// The selection of a set held in one place (the sequential render): values is reordered.
LuminanceSelection select_locally(std::vector<double>& values);

// Radix select: a non-negative or negative double as an unsigned key of the same order,
// read 8 bits at a time from the top (kSelectionRounds rounds of 256 buckets).
constexpr int kSelectionRounds = 8;
constexpr int kSelectionBuckets = 256;
std::uint64_t order_key(double value);
double from_order_key(std::uint64_t key);
// The bucket of `key` in round r (0 = the top 8 bits), and whether key's digits above
// round r equal `prefix`'s.
int key_digit(std::uint64_t key, int round);
bool key_matches(std::uint64_t key, std::uint64_t prefix, int round);

}  // namespace ncube

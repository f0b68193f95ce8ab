#include "render/exposure.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace ncube {
namespace {

constexpr double kPercentile = 0.95;      // this percentile of visible luminance ...
constexpr double kPercentileValue = 0.9;  // ... maps to this linear value (before sRGB)

}  // namespace


double srgb_encode(double c) {
  return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}

std::uint64_t percentile_rank(std::uint64_t count) {
  return count == 0 ? 0 : std::uint64_t(kPercentile * double(count - 1));
}

double exposure_scale(const LuminanceSelection& non_emitters, const LuminanceSelection& all) {
  const LuminanceSelection& v = non_emitters.count > 0 ? non_emitters : all;
  if (v.count == 0) return 1.0;
  double reference = v.kth;
  if (!(reference > 0.0)) reference = v.max;
  return reference > 0.0 ? kPercentileValue / reference : 1.0;
}

LuminanceSelection select_locally(std::vector<double>& values) {
  LuminanceSelection s;
  s.count = values.size();
  if (values.empty()) return s;
  auto nth = values.begin() + std::ptrdiff_t(percentile_rank(s.count));
  std::nth_element(values.begin(), nth, values.end());
  s.kth = *nth;
  s.max = *std::max_element(values.begin(), values.end());
  return s;
}

std::uint64_t order_key(double value) {
  std::uint64_t bits;
  std::memcpy(&bits, &value, sizeof bits);
  return bits >> 63 ? ~bits : bits | (std::uint64_t(1) << 63);
}

double from_order_key(std::uint64_t key) {
  const std::uint64_t bits = key >> 63 ? key & ~(std::uint64_t(1) << 63) : ~key;
  double value;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

int key_digit(std::uint64_t key, int round) { return int((key >> (56 - 8 * round)) & 0xff); }

bool key_matches(std::uint64_t key, std::uint64_t prefix, int round) {
  if (round == 0) return true;
  const int shift = 64 - 8 * round;
  return (key >> shift) == (prefix >> shift);
}

}  // namespace ncube

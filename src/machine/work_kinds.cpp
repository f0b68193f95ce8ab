#include "machine/work_kinds.h"

#include <algorithm>
#include <stdexcept>

namespace ncube {
namespace {

struct KindEntry {
  const char* cost_parameter;
  const char* rate;
  double PlatformConfig::*field;
};

struct Fallback {
  const char* rate;
  const char* fallback;
  double PlatformConfig::*field;
  double PlatformConfig::*fallback_field;
};

const std::vector<Fallback>& fallbacks() {
  static const std::vector<Fallback> entries = {
#define NCUBE_FALLBACK_ENTRY(rate, fallback) \
  {#rate, #fallback, &PlatformConfig::rate, &PlatformConfig::fallback},
      NCUBE_RATE_FALLBACKS(NCUBE_FALLBACK_ENTRY)
#undef NCUBE_FALLBACK_ENTRY
  };
  return entries;
}

const std::vector<KindEntry>& kind_entries() {
  static const std::vector<KindEntry> entries = {
#define NCUBE_KIND_ENTRY(cost, rate) {#cost, #rate, &PlatformConfig::rate},
      NCUBE_WORK_KINDS(NCUBE_KIND_ENTRY)
#undef NCUBE_KIND_ENTRY
  };
  return entries;
}

const KindEntry& entry_of(const char* cost_parameter) {
  for (const KindEntry& e : kind_entries())
    if (std::string(e.cost_parameter) == cost_parameter) return e;
  // tests/cost_model_test.cpp holds the list to the counters: reaching here is a defect.
  throw std::logic_error(std::string("src/machine/work_kinds.h: no kind of work for ") +
                         cost_parameter);
}

// The rate field of every counter, in the order of the counter lists (looked up once).
const std::vector<double PlatformConfig::*>& work_fields() {
  static const std::vector<double PlatformConfig::*> fields = {
#define NCUBE_KIND_FIELD(member, cost, doc) entry_of(#cost).field,
      NCUBE_WORK_COUNTERS(NCUBE_KIND_FIELD)
  };
  return fields;
}

const std::vector<double PlatformConfig::*>& render_fields() {
  static const std::vector<double PlatformConfig::*> fields = {
      NCUBE_RENDER_COUNTERS(NCUBE_KIND_FIELD)
#undef NCUBE_KIND_FIELD
  };
  return fields;
}

// The rate a kind runs at: its own, else its fallback's (NCUBE_RATE_FALLBACKS), else
// node_speed. The same double as the rate it falls back to, so that a machine leaving a rate
// out is charged to the last bit as before the rate existed.
double rate(const PlatformConfig& platform, double PlatformConfig::*field) {
  if (platform.*field > 0) return platform.*field;
  for (const Fallback& f : fallbacks())
    if (f.field == field) return rate(platform, f.fallback_field);
  return platform.node_speed;
}

}  // namespace

const std::vector<std::string>& work_rate_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (const KindEntry& e : kind_entries())
      if (std::find(out.begin(), out.end(), e.rate) == out.end()) out.push_back(e.rate);
    return out;
  }();
  return names;
}

std::string fallback_rate_of(const std::string& rate) {
  for (const Fallback& f : fallbacks())
    if (rate == f.rate) return f.fallback;
  return "";
}

std::string work_rate_of(const std::string& cost_parameter) {
  for (const KindEntry& e : kind_entries())
    if (cost_parameter == e.cost_parameter) return e.rate;
  return "";
}

double kind_flops(const CostModel& costs, const WorkCounts& c, const std::string& rate) {
  double flops = 0.0;
#define NCUBE_KIND_FLOPS(member, cost, doc) \
  if (entry_of(#cost).rate == rate) flops += costs.cost * double(c.member);
  NCUBE_WORK_COUNTERS(NCUBE_KIND_FLOPS)
#undef NCUBE_KIND_FLOPS
  return flops;
}

bool gives_work_rates(const PlatformConfig& platform) {
  for (const KindEntry& e : kind_entries())
    if (platform.*e.field > 0) return true;
  return false;
}

// Each counter's flops at its kind's rate, summed in the order of the counter list.
double compute_seconds(const CostModel& costs, const PlatformConfig& platform,
                       const WorkCounts& c) {
  if (!gives_work_rates(platform)) return costs.flops(c) / platform.node_speed;
  const auto& fields = work_fields();
  double seconds = 0.0;
  std::size_t k = 0;
#define NCUBE_ADD_SECONDS(member, cost, doc) \
  seconds += costs.cost * double(c.member) / rate(platform, fields[k++]);
  NCUBE_WORK_COUNTERS(NCUBE_ADD_SECONDS)
  return seconds;
}

double compute_seconds(const CostModel& costs, const PlatformConfig& platform,
                       const RenderCounts& c) {
  if (!gives_work_rates(platform)) return costs.flops(c) / platform.node_speed;
  const auto& fields = render_fields();
  double seconds = 0.0;
  std::size_t k = 0;
  NCUBE_RENDER_COUNTERS(NCUBE_ADD_SECONDS)
#undef NCUBE_ADD_SECONDS
  return seconds;
}

}  // namespace ncube

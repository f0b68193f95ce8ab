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

// A counter's own fallback (NCUBE_COUNTER_FALLBACKS): the rate field that runs it when the
// machine leaves its kind's rate out; null for a counter whose kind falls back as a whole.
double PlatformConfig::*counter_fallback_field(const char* cost_parameter) {
#define NCUBE_COUNTER_FALLBACK_FIELD(cost, fallback) \
  if (std::string(#cost) == cost_parameter) return &PlatformConfig::fallback;
  NCUBE_COUNTER_FALLBACKS(NCUBE_COUNTER_FALLBACK_FIELD)
#undef NCUBE_COUNTER_FALLBACK_FIELD
  return nullptr;
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

// Each counter's own fallback field, in the order of the counter lists (null: none).
const std::vector<double PlatformConfig::*>& work_fallback_fields() {
  static const std::vector<double PlatformConfig::*> fields = {
#define NCUBE_FALLBACK_FIELD(member, cost, doc) counter_fallback_field(#cost),
      NCUBE_WORK_COUNTERS(NCUBE_FALLBACK_FIELD)
#undef NCUBE_FALLBACK_FIELD
  };
  return fields;
}

// What decides whether each counter (in list order) is charged: `field` 0 for a counter always
// charged; else it is charged when the platform gives `field` (a host work counter's own
// rate) or, for a counter a host counter replaces, when it does not give it.
struct Gate {
  double PlatformConfig::*field = nullptr;
  bool charged_when_given = true;
};

const std::vector<Gate>& work_gates() {
  static const std::vector<Gate> gates = [] {
    std::vector<std::string> members;
#define NCUBE_MEMBER_NAME(member, cost, doc) members.push_back(#member);
    NCUBE_WORK_COUNTERS(NCUBE_MEMBER_NAME)
#undef NCUBE_MEMBER_NAME
    const auto index_of = [&members](const char* member) {
      return std::size_t(std::find(members.begin(), members.end(), member) - members.begin());
    };
    std::vector<Gate> out(members.size());
    for (std::size_t k = 0; k < members.size(); ++k)
      if (is_host_work_counter(members[k].c_str())) out[k] = {work_fields()[k], true};
#define NCUBE_REPLACED_GATE(host, paper) \
  out.at(index_of(#paper)) = {work_fields()[index_of(#host)], false};
    NCUBE_HOST_REPLACES(NCUBE_REPLACED_GATE)
#undef NCUBE_REPLACED_GATE
    return out;
  }();
  return gates;
}

bool charged(const PlatformConfig& platform, const Gate& gate) {
  return !gate.field || (platform.*gate.field > 0) == gate.charged_when_given;
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

// The rate of a counter of kind `field` whose own fallback is `fallback` (null: none): the
// kind's rate when the machine gives it, else the fallback's as rate() finds it.
double counter_rate(const PlatformConfig& platform, double PlatformConfig::*field,
                    double PlatformConfig::*fallback) {
  if (fallback && !(platform.*field > 0)) return rate(platform, fallback);
  return rate(platform, field);
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
  std::size_t k = 0;
#define NCUBE_KIND_FLOPS(member, cost, doc)                                                   \
  if (entry_of(#cost).rate == rate &&                                                         \
      (!work_gates()[k].field || work_gates()[k].charged_when_given))                         \
    flops += costs.cost * double(c.member);                                                   \
  ++k;
  NCUBE_WORK_COUNTERS(NCUBE_KIND_FLOPS)
#undef NCUBE_KIND_FLOPS
  return flops;
}

bool charges_counter(const PlatformConfig& platform, const std::string& member) {
  std::size_t k = 0;
#define NCUBE_FIND_GATE(m, cost, doc) \
  if (member == #m) return charged(platform, work_gates()[k]); \
  ++k;
  NCUBE_WORK_COUNTERS(NCUBE_FIND_GATE)
#undef NCUBE_FIND_GATE
  return false;
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
  const auto& gates = work_gates();
  const auto& counter_fallbacks = work_fallback_fields();
  double seconds = 0.0;
  std::size_t k = 0;
#define NCUBE_ADD_WORK_SECONDS(member, cost, doc)                                \
  if (charged(platform, gates[k]))                                              \
    seconds += costs.cost * double(c.member) /                                  \
               counter_rate(platform, fields[k], counter_fallbacks[k]);          \
  ++k;
  NCUBE_WORK_COUNTERS(NCUBE_ADD_WORK_SECONDS)
#undef NCUBE_ADD_WORK_SECONDS
  return seconds;
}

double compute_seconds(const CostModel& costs, const PlatformConfig& platform,
                       const RenderCounts& c) {
  if (!gives_work_rates(platform)) return costs.flops(c) / platform.node_speed;
  const auto& fields = render_fields();
  double seconds = 0.0;
  std::size_t k = 0;
#define NCUBE_ADD_SECONDS(member, cost, doc) \
  seconds += costs.cost * double(c.member) / rate(platform, fields[k++]);
  NCUBE_RENDER_COUNTERS(NCUBE_ADD_SECONDS)
#undef NCUBE_ADD_SECONDS
  return seconds;
}

}  // namespace ncube

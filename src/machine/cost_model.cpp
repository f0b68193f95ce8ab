#include "machine/cost_model.h"

#include "machine/parameter_file.h"

namespace ncube {

// The sum runs in the order of the list, as the hand-written sum did before it. The host work
// counters are left out: they are charged only at their own rates (work_kinds.h).
double CostModel::flops(const WorkCounts& c) const {
  double total = 0.0;
#define NCUBE_ADD_WORK_FLOPS(member, cost, doc) \
  if (!is_host_work_counter(#member)) total += cost * double(c.member);
  NCUBE_WORK_COUNTERS(NCUBE_ADD_WORK_FLOPS)
#undef NCUBE_ADD_WORK_FLOPS
  return total;
}

double CostModel::flops(const RenderCounts& c) const {
  double total = 0.0;
#define NCUBE_ADD_FLOPS(member, cost, doc) total += cost * double(c.member);
  NCUBE_RENDER_COUNTERS(NCUBE_ADD_FLOPS)
#undef NCUBE_ADD_FLOPS
  return total;
}

double CostModel::bytes(const HeldItems& items) const {
  double total = 0.0;
#define NCUBE_ADD_BYTES(member, size, doc) total += items.member * size;
  NCUBE_HELD_ITEMS(NCUBE_ADD_BYTES)
#undef NCUBE_ADD_BYTES
  return total;
}

const std::vector<CostParameter>& cost_parameters() {
  static const std::vector<CostParameter> parameters = {
#define NCUBE_FLOPS_PARAMETER(member, cost, doc) {#cost, &CostModel::cost},
      NCUBE_WORK_COUNTERS(NCUBE_FLOPS_PARAMETER) NCUBE_RENDER_COUNTERS(NCUBE_FLOPS_PARAMETER)
#undef NCUBE_FLOPS_PARAMETER
#define NCUBE_SIZE_PARAMETER(name, min, max, doc) {#name, &CostModel::name},
          NCUBE_DATA_SIZES(NCUBE_SIZE_PARAMETER)
#undef NCUBE_SIZE_PARAMETER
  };
  return parameters;
}

CostModel load_cost_model(const std::string& path) {
  // Sanity bound (a typo, not a model, beyond it): flops per operation up to 1e9.
  constexpr double kFlops = 1e9;
  const std::vector<ParameterSpec> specs = {
#define NCUBE_FLOPS_SPEC(member, cost, doc) {#cost, 0, false, kFlops},
      NCUBE_WORK_COUNTERS(NCUBE_FLOPS_SPEC) NCUBE_RENDER_COUNTERS(NCUBE_FLOPS_SPEC)
#undef NCUBE_FLOPS_SPEC
#define NCUBE_SIZE_SPEC(name, min, max, doc) {#name, min, true, max},
          NCUBE_DATA_SIZES(NCUBE_SIZE_SPEC)
#undef NCUBE_SIZE_SPEC
  };
  const auto values = read_parameter_file(path, kCostModelFile, specs);
  CostModel m;
  for (const CostParameter& p : cost_parameters()) m.*p.field = values.at(p.name);
  return m;
}

}  // namespace ncube

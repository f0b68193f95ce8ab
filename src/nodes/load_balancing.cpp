#include "nodes/load_balancing.h"

#include <algorithm>
#include <numeric>

namespace ncube {

BalanceDecision plan_transfers(const std::vector<ProcessorLoad>& loads, double node_memory,
                               const BalancingOptions& options) {
  BalanceDecision decision;
  const int R = int(loads.size());
  std::vector<bool> busy(std::size_t(R), false);  // already in a transfer this time
  // 1. Memory.
  for (const ProcessorLoad& short_of : loads) {
    if (short_of.wanted_bytes <= 0.0) continue;
    int best = -1;
    for (const ProcessorLoad& other : loads)
      if (other.rank != short_of.rank && !busy[std::size_t(other.rank)] &&
          (best < 0 || other.bytes < loads[std::size_t(best)].bytes))
        best = other.rank;
    const double room = best >= 0 ? 0.5 * (node_memory - loads[std::size_t(best)].bytes) : 0.0;
    if (!options.enabled || busy[std::size_t(short_of.rank)] || best < 0 ||
        short_of.smallest_patch_bytes <= 0.0 || short_of.smallest_patch_bytes > room) {
      decision.out_of_memory_rank = short_of.rank;
      decision.out_of_memory_needed = short_of.bytes + short_of.wanted_bytes;
      return decision;
    }
    busy[std::size_t(short_of.rank)] = busy[std::size_t(best)] = true;
    decision.transfers.push_back({short_of.rank, best, short_of.elements, room});
  }
  if (!options.enabled || R < 2) return decision;
  // 2. Elements.
  const double mean =
      std::accumulate(loads.begin(), loads.end(), 0.0,
                      [](double sum, const ProcessorLoad& l) { return sum + double(l.elements); }) / R;
  std::vector<int> order(static_cast<std::size_t>(R));
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&loads](int a, int b) {
    return loads[std::size_t(a)].elements > loads[std::size_t(b)].elements;
  });
  int low = R - 1;
  for (int high = 0; high < low; ++high) {
    const ProcessorLoad& from = loads[std::size_t(order[std::size_t(high)])];
    if (double(from.elements) <= (1.0 + options.threshold) * mean) break;
    if (busy[std::size_t(from.rank)]) continue;
    while (low > high && busy[std::size_t(order[std::size_t(low)])]) --low;
    if (low <= high) break;
    const ProcessorLoad& to = loads[std::size_t(order[std::size_t(low)])];
    if (double(to.elements) >= mean) break;
    const long elements = long(std::min(double(from.elements) - mean, mean - double(to.elements)));
    const double room = 0.5 * (node_memory - to.bytes);
    // An order its sender could not fill would cost a message and move nothing.
    if (from.smallest_patch_elements <= 0 || from.smallest_patch_elements > elements ||
        from.smallest_patch_bytes > room)
      continue;
    decision.transfers.push_back({from.rank, to.rank, elements, room});
    busy[std::size_t(from.rank)] = busy[std::size_t(to.rank)] = true;
    --low;
  }
  return decision;
}

long patch_records(const Scene& scene, const StoredPatch& patch) {
  const Patch& p = scene.patches[std::size_t(patch.patch)];
  // Leaves L from the nu x nv grid after c cuts: L = nu nv + 3c; records = nu nv + 4c.
  const long cuts = (long(patch.elements.size()) - p.element_count()) / 3;
  return p.element_count() + 4 * cuts;
}

double patch_record_bytes(long records, bool with_geometry, const CostModel& costs) {
  return costs.patch_radiosity_bytes + (with_geometry ? costs.patch_geometry_bytes : 0.0) +
         double(records) * costs.element_bytes;
}

double patch_bytes(const Scene& scene, const StoredPatch& patch, const CostModel& costs,
                   bool with_geometry) {
  return patch_record_bytes(patch_records(scene, patch), with_geometry, costs);
}

std::vector<int> patches_to_move(const ElementStore& store, const Transfer& transfer, int shooter,
                                 const CostModel& costs, bool with_geometry) {
  std::vector<const StoredPatch*> candidates;
  for (const StoredPatch& s : store.patches())
    if (s.patch != shooter) candidates.push_back(&s);
  std::stable_sort(candidates.begin(), candidates.end(), [](const StoredPatch* a, const StoredPatch* b) {
    return a->elements.size() > b->elements.size();
  });
  std::vector<int> moved;
  long elements = 0;
  double bytes = 0.0;
  for (const StoredPatch* s : candidates) {
    const double b = patch_bytes(store.scene(), *s, costs, with_geometry);
    if (elements + long(s->elements.size()) > transfer.elements || bytes + b > transfer.bytes) continue;
    elements += long(s->elements.size());
    bytes += b;
    moved.push_back(s->patch);
  }
  std::sort(moved.begin(), moved.end());
  return moved;
}

}  // namespace ncube

// Dynamic load balancing (paper section 4.2): "As we find that a processor has a
// significantly higher number of elements than other processors, we can transfer some
// patches and the associated elements to a less loaded processor. This strategy can also be
// used if we run out of memory while adaptively subdividing."
//
// Rule (a choice, docs/model.md "Load balancing"): at every shooter selection the master
// learns each radiosity processor's load (elements, bytes, bytes it could not get for cuts).
//  1. Memory first: a processor that could not make its cuts gives patches to the processor
//     with the most free memory, up to half of that free memory; if even its smallest
//     movable patch does not fit there, the run ends out of memory.
//  2. Elements: processors with more than (1 + threshold) x the mean element count are paired,
//     most loaded first, with those below the mean, least loaded first; each pair moves
//     patches of up to the smaller of the two distances to the mean, in elements, and only
//     when the sender's smallest movable patch fits (so no order moves nothing).
// The sender chooses the patches: largest element count first (ties: lower patch index),
// never the shooter, each only if it keeps within the order's elements and bytes.
#pragma once

#include <vector>

#include "machine/cost_model.h"
#include "radiosity/element_store.h"

namespace ncube {

struct BalancingOptions {
  bool enabled = false;    // --balance
  double threshold = 0.2;  // --balance-threshold: "significantly" = 20 % above the mean
};

// What a radiosity processor reports with its shooter candidate (when its load can change:
// subdivision or balancing on).
struct ProcessorLoad {
  int rank = 0;
  long elements = 0;
  double bytes = 0.0;                 // its memory now
  double wanted_bytes = 0.0;          // bytes of the cuts it could not make (no room)
  // Its smallest movable patch (fewest element records): never its own shooter candidate,
  // the one patch of it the master may choose as shooter. 0: none movable.
  double smallest_patch_bytes = 0.0;
  long smallest_patch_elements = 0;
};

// "Move patches with at most `elements` elements and `bytes` bytes from `from` to `to`."
struct Transfer {
  int from = 0, to = 0;
  long elements = 0;
  double bytes = 0.0;
};

struct BalanceDecision {
  std::vector<Transfer> transfers;
  int out_of_memory_rank = -1;  // a processor that cannot make its cuts and cannot move
  double out_of_memory_needed = 0.0;
};

// The master's decision. `node_memory`: bytes per node (infinite without a memory cap).
BalanceDecision plan_transfers(const std::vector<ProcessorLoad>& loads, double node_memory,
                               const BalancingOptions& options);

// The element records a held patch takes: every element ever made (a cut keeps its parent
// as a quadtree node).
long patch_records(const Scene& scene, const StoredPatch& patch);
// The modeled bytes of a patch with `records` element records as it travels and as it is
// held: its radiosity data, its geometry when radiosity processors hold only their own
// (V > 0, section 3), and its element records.
double patch_record_bytes(long records, bool with_geometry, const CostModel& costs);
// The same for a held patch.
double patch_bytes(const Scene& scene, const StoredPatch& patch, const CostModel& costs,
                   bool with_geometry);

// The sender's choice for `transfer`: held patches, never `shooter`.
std::vector<int> patches_to_move(const ElementStore& store, const Transfer& transfer, int shooter,
                                 const CostModel& costs, bool with_geometry);

}  // namespace ncube

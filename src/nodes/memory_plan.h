// What each node holds, in the modeled bytes of cost_model.json, checked against the
// node's memory (platforms/ncube2.json). The programs allocate everything when they start,
// so without adaptive subdivision (section 4.1) and load balancing (4.2) the peak is known
// before the first iteration; with them this plan is each node's start, and its bytes then
// change as it cuts, gives and receives patches (docs/model.md, "Memory").
#pragma once

#include <string>
#include <vector>

#include "machine/cost_model.h"
#include "nodes/node_role.h"
#include "nodes/program_setup.h"

namespace ncube {

struct NodeMemory {
  int node = 0;
  NodeRole role = NodeRole::kRadiosity;
  int rank = 0;
  double bytes = 0.0;
};

// The search structure of the run's visibility method over `patches`
// (OccluderSet::structure_items, weighed by the cost model; section 6: the octree's cells and
// its leaves' patch lists).
double search_structure_bytes(const ProgramSetup& setup, const std::vector<int>& patches,
                              const CostModel& costs);

// One entry per node in use, in node order.
std::vector<NodeMemory> plan_memory(const ProgramSetup& setup,
                                    const std::vector<std::vector<int>>& owned_patches,
                                    const CostModel& costs);

// The shooter-centred scheme (--parallelisation shooters, V = 0): one entry per node, each
// holding the whole scene (geometry, search structure, every patch's radiosity data and
// every element), the shooter records, and two increment vectors (its own sum and the one
// being received).
std::vector<NodeMemory> plan_shooter_memory(const ProgramSetup& setup, const CostModel& costs);

// Çapın, Aykanat & Özgüç's circulation scheme (--parallelisation circulation, V = 0): node
// rank holds the whole scene's geometry and search structure (for its shooter's form factors
// to every element), its owned patches' radiosity data and elements, the R candidates of a
// gathering round and the one being passed on, its shot's increments for every element of the
// scene, and two blocks of the light distribution (the one it adds to and the one arriving):
// the largest block, at most.
std::vector<NodeMemory> plan_circulation_memory(const ProgramSetup& setup,
                                                const std::vector<std::vector<int>>& owned_patches,
                                                const CostModel& costs);

}  // namespace ncube

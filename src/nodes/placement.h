// Where the node programs run on the hypercube, and which patches each one holds.
//
// Placement rule: radiosity processor r and its V visibility processors form group r, which
// occupies the V + 1 consecutive node addresses r(V+1) .. r(V+1)+V; the radiosity processor
// is the first of them. When V + 1 is a power of two the group is an aligned subcube (its
// nodes differ only in the low log2(V+1) address bits, at most that many hops apart) and the
// radiosity processors of neighbouring ranks are hypercube neighbours; other V still get
// compact consecutive blocks (e.g. R=5, V=11 uses nodes 0..59). The master is radiosity
// processor 0 on node 0 (paper section 5: "the first radiosity processor").
#pragma once

#include <vector>

#include "scene/scene.h"

namespace ncube {

struct Placement {
  int radiosity_processors = 1;
  int visibility_processors = 0;  // per radiosity processor
  int radiosity_node(int rank) const { return rank * (visibility_processors + 1); }
  int visibility_node(int rank, int j) const { return radiosity_node(rank) + 1 + j; }
  int node_count() const { return radiosity_processors * (visibility_processors + 1); }
};

// Section 4: patches go to radiosity processors so that each handles about the same number
// of elements. Largest patches first, each to the processor with the fewest elements so far
// (ties: the lower rank); each processor's list is in scene order.
std::vector<std::vector<int>> partition_patches_by_elements(const Scene& scene, int processors);

// Section 3: each of a group's V visibility processors stores an even 1/V share of all
// patches: share j is the j-th of V consecutive runs of scene patches (sizes differ by at
// most one).
std::vector<int> visibility_share(const Scene& scene, int shares, int j);

}  // namespace ncube

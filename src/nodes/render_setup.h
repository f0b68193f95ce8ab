// The rendering phase after the radiosity run (paper section 2.3): what its node programs
// share, the order of the ring, and each node's memory.
//
// Choices (docs/model.md, "Parallel rendering"): all N = R x (V + 1) nodes of the run take
// part, node k rendering part k of the picture; a radiosity processor starts with the
// render records of the elements of the patches it owns, a visibility processor with none.
#pragma once

#include <vector>

#include "machine/cost_model.h"
#include "nodes/messages.h"
#include "render/row_share.h"
#include "scene/scene.h"

namespace ncube {

// How every node gets every element: around a ring (N - 1 steps, each node passing on what
// it received) or over the hypercube (recursive doubling, log2 N steps: in step d each node
// exchanges all it holds with its neighbour across dimension d).
enum class RenderDistribution { kRing, kHypercube };
const char* render_distribution_name(RenderDistribution distribution);

struct RenderOptions {
  bool enabled = false;  // --render-parallel given
  RowPartition partition = RowPartition::kBlocks;
  RenderDistribution distribution = RenderDistribution::kHypercube;
  int width = 800, height = 600;
  bool outline_elements = false;  // --outline-elements: the picture shows the element edges
};

struct RenderSetup {
  const Scene& scene;
  RenderOptions options;
  int nodes = 1;                     // N
  std::vector<ElementShare> shares;  // per node: the records it starts with

  RowShare rows_of(int node) const {
    return {options.height, nodes, node, options.partition};
  }
};

bool is_power_of_two(int n);

// The ring: position p holds node ring_node(p). On a power-of-two node count the ring
// follows the Gray code, so each step is one hypercube hop; otherwise node order.
int ring_node(int position, int nodes);
int ring_position(int node, int nodes);

// The start records of every node: radiosity processor r's owned patches (in scene order),
// nothing on a visibility processor. `solution` as for render_elements.
std::vector<ElementShare> starting_shares(const Scene& scene,
                                          const std::vector<PatchSolution>& solution,
                                          const std::vector<std::vector<int>>& owned_patches,
                                          int visibility_processors);

// Modeled bytes of render records as sent and held: render_element_bytes for a record with
// its corners, render_vertex_bytes more for each T-vertex on its boundary.
double render_record_bytes(const std::vector<RenderElement>& records, const CostModel& costs);
// The same for each node's starting share.
std::vector<double> share_bytes(const std::vector<ElementShare>& shares, const CostModel& costs);

// Each node's peak bytes in the rendering phase, from the bytes of each node's starting
// share: the largest of
//  - distributing and rasterising: reserve + its frame share (rows x width x 9 samples) +
//    the records it holds at once (ring: the share it passes on and the one arriving, at
//    most; hypercube: in the end all of them);
//  - resolving: reserve + its frame share + its finished rows;
//  - node 0 collecting: reserve + the whole picture's pixels.
// With no records (all shares 0 bytes) it is the part that does not depend on the solution.
std::vector<double> plan_render_memory(const RenderOptions& options, int nodes,
                                       const std::vector<double>& starting_share_bytes,
                                       const CostModel& costs);

}  // namespace ncube

#include "nodes/memory_plan.h"

#include <algorithm>

#include "nodes/messages.h"
#include "radiosity/form_factor_methods.h"
#include "visibility/visibility_methods.h"

namespace ncube {

double search_structure_bytes(const ProgramSetup& setup, const std::vector<int>& patches,
                              const CostModel& costs) {
  const VisibilityMethod& method = visibility_methods().at(setup.options.visibility);
  return costs.bytes(
      method.reference(setup.scene, patches, setup.options.ray_policy)->structure_items());
}

namespace {

// What the run's form-factor method holds on a node that computes form factors.
double method_bytes(const ProgramSetup& setup, const CostModel& costs) {
  return costs.bytes(form_factor_methods().at(setup.options.form_factors).node_items(setup.options));
}

}  // namespace

std::vector<NodeMemory> plan_memory(const ProgramSetup& setup,
                                    const std::vector<std::vector<int>>& owned_patches,
                                    const CostModel& costs) {
  const Placement& p = setup.placement;
  const int V = p.visibility_processors;
  const double patches = double(setup.scene.patches.size());
  const double mask_bytes = part_mask_bytes(setup.options.samples);
  const double block = setup.block_size;
  const double in_flight = setup.pipelined ? 2.0 : 1.0;
  // Two shooter records: the one being shot and the one being chosen.
  const double records = 2.0 * costs.shooter_record_bytes;
  // A node that tests rays also holds its visibility method's search structure over its set
  // (the whole scene, or its share; section 6: the octree); shares are the same for every
  // group.
  const double whole_structure =
      V == 0 ? search_structure_bytes(setup, visibility_share(setup.scene, 1, 0), costs) : 0.0;
  const double form_factor_bytes =
      method_bytes(setup, costs);
  std::vector<double> share_structure(std::size_t(V), 0.0), share_patches(std::size_t(V), 0.0);
  for (int j = 0; j < V; ++j) {
    const std::vector<int> share = visibility_share(setup.scene, V, j);
    share_patches[std::size_t(j)] = double(share.size());
    share_structure[std::size_t(j)] = search_structure_bytes(setup, share, costs);
  }
  std::vector<NodeMemory> nodes;
  for (int rank = 0; rank < p.radiosity_processors; ++rank) {
    double owned_elements = 0.0;
    for (int patch : owned_patches[rank])
      owned_elements += setup.scene.patches[patch].element_count();
    const double owned = double(owned_patches[rank].size());
    NodeMemory rp{p.radiosity_node(rank), NodeRole::kRadiosity, rank, costs.node_reserve_bytes + records};
    // Section 2.2: without visibility processors every radiosity processor holds the
    // geometry of all patches; section 3: with them, only its own.
    rp.bytes += (V == 0 ? patches : owned) * costs.patch_geometry_bytes + whole_structure;
    // With V = 0 it computes the form factors itself: its method's buffers (the hemicube's).
    if (V == 0) rp.bytes += form_factor_bytes;
    rp.bytes += owned * costs.patch_radiosity_bytes + owned_elements * costs.element_bytes;
    if (V > 0)  // a block of points out, V blocks of answers in
      rp.bytes += in_flight * block * (costs.point_bytes + V * mask_bytes);
    nodes.push_back(rp);
    for (int j = 0; j < V; ++j) {
      const double share = share_patches[std::size_t(j)];
      NodeMemory vp{p.visibility_node(rank, j), NodeRole::kVisibility, rank,
                    costs.node_reserve_bytes + records + share * costs.patch_geometry_bytes +
                        in_flight * block * (costs.point_bytes + mask_bytes) +
                        share_structure[std::size_t(j)]};
      nodes.push_back(vp);
    }
  }
  return nodes;
}

std::vector<NodeMemory> plan_shooter_memory(const ProgramSetup& setup, const CostModel& costs) {
  const double patches = double(setup.scene.patches.size());
  const double elements = double(setup.scene.element_total());
  const double structure =
      search_structure_bytes(setup, visibility_share(setup.scene, 1, 0), costs);
  // As a radiosity processor of the paper's program without visibility processors holding
  // every patch (section 2.2's first version), plus its vector of increments and the one it
  // receives in each step of the exchange.
  const double bytes = costs.node_reserve_bytes + 2.0 * costs.shooter_record_bytes +
                       patches * (costs.patch_geometry_bytes + costs.patch_radiosity_bytes) +
                       structure + elements * costs.element_bytes +
                       2.0 * elements * costs.radiosity_increment_bytes +
                       method_bytes(setup, costs);
  std::vector<NodeMemory> nodes;
  for (int rank = 0; rank < setup.placement.radiosity_processors; ++rank)
    nodes.push_back({setup.placement.radiosity_node(rank), NodeRole::kRadiosity, rank, bytes});
  return nodes;
}

std::vector<NodeMemory> plan_circulation_memory(const ProgramSetup& setup,
                                                const std::vector<std::vector<int>>& owned_patches,
                                                const CostModel& costs) {
  const int R = setup.placement.radiosity_processors;
  const double elements = double(setup.scene.element_total());
  double largest_block = 0.0;
  std::vector<double> owned_elements;
  for (const std::vector<int>& patches : owned_patches) {
    double count = 0.0;
    for (int patch : patches) count += setup.scene.patches[std::size_t(patch)].element_count();
    owned_elements.push_back(count);
    largest_block = std::max(largest_block, count);
  }
  const double shared = costs.node_reserve_bytes + (R + 1.0) * costs.shooter_record_bytes +
                        double(setup.scene.patches.size()) * costs.patch_geometry_bytes +
                        search_structure_bytes(setup, visibility_share(setup.scene, 1, 0), costs) +
                        method_bytes(setup, costs) +
                        elements * costs.radiosity_increment_bytes +
                        2.0 * largest_block * costs.radiosity_increment_bytes;
  std::vector<NodeMemory> nodes;
  for (int rank = 0; rank < R; ++rank)
    nodes.push_back({setup.placement.radiosity_node(rank), NodeRole::kRadiosity, rank,
                     shared + double(owned_patches[std::size_t(rank)].size()) * costs.patch_radiosity_bytes +
                         owned_elements[std::size_t(rank)] * costs.element_bytes});
  return nodes;
}

}  // namespace ncube

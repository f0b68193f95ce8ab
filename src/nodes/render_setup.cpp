#include "nodes/render_setup.h"

#include <algorithm>
#include <numeric>

#include "render/frame_share.h"

namespace ncube {

const char* render_distribution_name(RenderDistribution distribution) {
  return distribution == RenderDistribution::kRing ? "ring" : "hypercube";
}

bool is_power_of_two(int n) { return n > 0 && (n & (n - 1)) == 0; }

int ring_node(int position, int nodes) {
  return is_power_of_two(nodes) ? position ^ (position >> 1) : position;
}

int ring_position(int node, int nodes) {
  if (!is_power_of_two(nodes)) return node;
  int position = 0;
  for (int g = node; g; g >>= 1) position ^= g;  // inverse Gray code
  return position;
}

std::vector<ElementShare> starting_shares(const Scene& scene,
                                          const std::vector<PatchSolution>& solution,
                                          const std::vector<std::vector<int>>& owned_patches,
                                          int visibility_processors) {
  std::vector<ElementShare> shares;
  const auto none = std::make_shared<const std::vector<RenderElement>>();
  for (const std::vector<int>& owned : owned_patches) {
    shares.push_back(std::make_shared<const std::vector<RenderElement>>(
        render_elements(scene, solution, owned)));
    for (int j = 0; j < visibility_processors; ++j) shares.push_back(none);
  }
  return shares;
}

double render_record_bytes(const std::vector<RenderElement>& records, const CostModel& costs) {
  double t_vertices = 0.0;
  for (const RenderElement& r : records) t_vertices += double(r.t_vertices());
  return double(records.size()) * costs.render_element_bytes + t_vertices * costs.render_vertex_bytes;
}

std::vector<double> share_bytes(const std::vector<ElementShare>& shares, const CostModel& costs) {
  std::vector<double> bytes;
  for (const ElementShare& share : shares) bytes.push_back(render_record_bytes(*share, costs));
  return bytes;
}

std::vector<double> plan_render_memory(const RenderOptions& options, int nodes,
                                       const std::vector<double>& starting_share_bytes,
                                       const CostModel& costs) {
  const double all_bytes =
      std::accumulate(starting_share_bytes.begin(), starting_share_bytes.end(), 0.0);
  const double samples_per_row = double(options.width) * kSamplesPerAxis * kSamplesPerAxis;
  std::vector<double> peak;
  for (int node = 0; node < nodes; ++node) {
    const RowShare rows{options.height, nodes, node, options.partition};
    const double frame = rows.count() * samples_per_row * costs.frame_sample_bytes;
    double held = all_bytes;
    if (options.distribution == RenderDistribution::kRing) {
      // In step s the node passes on what arrived in step s - 1 (its own in step 1) while
      // the share of the node s places before it arrives.
      const int p = ring_position(node, nodes);
      const auto share = [&](int s) {
        return starting_share_bytes[std::size_t(ring_node(((p - s) % nodes + nodes) % nodes, nodes))];
      };
      held = share(0);
      for (int s = 1; s < nodes; ++s) held = std::max(held, share(s - 1) + share(s));
    }
    const double distributing = frame + held;
    const double resolving = frame + rows.count() * double(options.width) * costs.pixel_bytes;
    double bytes = std::max(distributing, resolving);
    if (node == 0)
      bytes = std::max(bytes, double(options.width) * options.height * costs.pixel_bytes);
    peak.push_back(costs.node_reserve_bytes + bytes);
  }
  return peak;
}

}  // namespace ncube

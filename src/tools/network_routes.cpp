#include "tools/network_routes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <simgrid/s4u/Host.hpp>
#include <simgrid/s4u/Link.hpp>

namespace ncube {
namespace {

// Whether route a is shorter than route b: by latency (sums of the same latencies in another
// order differ in the last bits, so within a relative 1e-9 they are equal), then fewer links,
// then a wider bottleneck.
bool shorter(const NodeRoute& a, const NodeRoute& b) {
  const double scale = std::max(std::abs(a.latency), std::abs(b.latency));
  if (std::abs(a.latency - b.latency) > 1e-9 * scale) return a.latency < b.latency;
  if (a.links != b.links) return a.links < b.links;
  return a.bottleneck_bandwidth > b.bottleneck_bandwidth;
}

}  // namespace

NodeRoute node_route(const std::vector<simgrid::s4u::Host*>& nodes, int from, int to) {
  std::vector<simgrid::s4u::Link*> links;
  double latency = 0.0;  // route_to adds to it
  nodes.at(std::size_t(from))->route_to(nodes.at(std::size_t(to)), links, &latency);
  NodeRoute route;
  route.from = from;
  route.to = to;
  route.links = int(links.size());
  route.latency = latency;
  route.bottleneck_bandwidth = std::numeric_limits<double>::infinity();
  for (const simgrid::s4u::Link* link : links)
    route.bottleneck_bandwidth = std::min(route.bottleneck_bandwidth, link->get_bandwidth());
  return route;
}

NodeRoute nearest_to_node0(const std::vector<simgrid::s4u::Host*>& nodes) {
  if (nodes.size() < 2) throw std::invalid_argument("nearest_to_node0: a platform of one node");
  // Ties keep the lower node number (searched in order).
  NodeRoute best = node_route(nodes, 0, 1);
  for (int to = 2; to < int(nodes.size()); ++to) {
    const NodeRoute route = node_route(nodes, 0, to);
    if (shorter(route, best)) best = route;
  }
  return best;
}

NodeRoute farthest_pair(const std::vector<simgrid::s4u::Host*>& nodes) {
  if (nodes.size() < 2) throw std::invalid_argument("farthest_pair: a platform of one node");
  // Ties keep the first pair found (lowest from, then lowest to).
  const int n = int(nodes.size());
  const int sources = n <= kAllPairsNodes ? n : 1;
  NodeRoute best = node_route(nodes, 0, 1);
  for (int from = 0; from < sources; ++from)
    for (int to = 0; to < n; ++to) {
      if (to == from) continue;
      const NodeRoute route = node_route(nodes, from, to);
      if (shorter(best, route)) best = route;
    }
  return best;
}

}  // namespace ncube

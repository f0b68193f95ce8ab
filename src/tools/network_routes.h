// The routes a network benchmark measures, read from the platform's own routing (SimGrid's
// route between two hosts: its links and their summed latency), so that any platform file
// (a hypercube, a torus, a fat tree, a mesh routed by Floyd) gives its own pairs
// (docs/network-benchmark.md).
#pragma once

#include <vector>

#include <simgrid/forward.h>

namespace ncube {

struct NodeRoute {
  int from = 0;
  int to = 0;
  int links = 0;                      // links on the route (hops; a cluster's private links count)
  double latency = 0.0;               // s, summed over the links
  double bottleneck_bandwidth = 0.0;  // bytes/s of the slowest link
};

// The route SimGrid takes from node `from` to node `to` (`nodes` in node order).
NodeRoute node_route(const std::vector<simgrid::s4u::Host*>& nodes, int from, int to);

// Node 0 and its nearest node: the smallest route latency, then the fewest links, then the
// widest bottleneck, then the lowest node number. Needs two nodes or more.
NodeRoute nearest_to_node0(const std::vector<simgrid::s4u::Host*>& nodes);

// The farthest pair: the largest route latency, then the most links, then the narrowest
// bottleneck, then the lowest node numbers. Every ordered pair is searched up to
// kAllPairsNodes nodes; beyond that, the routes from node 0 (the project's large platforms
// are hypercubes, where every node sees the same distances).
constexpr int kAllPairsNodes = 1024;
NodeRoute farthest_pair(const std::vector<simgrid::s4u::Host*>& nodes);

}  // namespace ncube

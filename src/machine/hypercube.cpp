#include "machine/hypercube.h"

#include <bitset>
#include <simgrid/s4u/Link.hpp>
#include <simgrid/s4u/NetZone.hpp>
#include <string>

namespace ncube {

std::vector<simgrid::s4u::Host*> build_hypercube(const PlatformConfig& config) {
  namespace s4u = simgrid::s4u;
  std::vector<s4u::Host*> hosts(std::size_t(config.node_count()), nullptr);
  const double speed = config.node_speed;
  auto make_node = [&hosts, speed](s4u::NetZone* zone, const std::vector<unsigned long>&,
                                   unsigned long rank) {
    // A torus of extent 2 in every dimension is a hypercube. The zone routes on the rank,
    // dimension by dimension from its bit 0 upward, so with address = rank this is e-cube
    // routing from address bit 0 upward. (The coordinate vector the zone passes lists the
    // rank's bits from the top one down, so it must not be read as bit k = coord[k].)
    const unsigned long address = rank;
    s4u::Host* host = zone->create_host("node-" + std::to_string(address), speed);
    hosts[address] = host;
    return std::make_pair(host->get_netpoint(), nullptr);
  };
  // A node sending to itself (never done by the node programs) needs a route too.
  auto make_loopback = [](s4u::NetZone* zone, const std::vector<unsigned long>&, unsigned long id) {
    return zone->create_link("loopback-" + std::to_string(id), 1e15)->set_latency(0)->seal();
  };
  const std::vector<unsigned long> dimensions(std::size_t(config.dimension), 2);
  s4u::ClusterCallbacks callbacks(make_node, make_loopback, {});
  if (config.dimension == 0) {
    // A single node: no links at all.
    s4u::NetZone* zone = s4u::create_full_zone("ncube");
    hosts[0] = zone->create_host("node-0", speed);
    zone->seal();
    return hosts;
  }
  s4u::NetZone* zone = s4u::create_torus_zone("ncube", nullptr, dimensions, callbacks,
                                              config.link_bandwidth, config.hop_latency,
                                              s4u::Link::SharingPolicy::SPLITDUPLEX);
  zone->seal();
  return hosts;
}

int hypercube_hops(int from, int to) { return int(std::bitset<32>(unsigned(from ^ to)).count()); }

}  // namespace ncube

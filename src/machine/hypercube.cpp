#include "machine/hypercube.h"

#include <bitset>
#include <simgrid/s4u/Link.hpp>
#include <simgrid/s4u/NetZone.hpp>
#include <string>

namespace ncube {
namespace {

// Tells SimGrid the platform is complete, as its XML reader does at </platform>, before the
// zone is sealed. SimGrid 3.32's tracer (tracing:yes) adds a Paje container for each link it
// is told of until then, and Link::seal() tells it again on every call: sealing the zone
// seals each link a second time, which ended the run with "container loopback-0 already
// present in all_containers_". The tracer then writes the platform's graph, which needs
// every host's container: the hosts are sealed as they are made, as the XML reader does.
// No simulated time moves (tests/simgrid_tracing_test.sh compares the result files).
void announce_platform_built() { simgrid::s4u::Engine::on_platform_created(); }

}  // namespace

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
    s4u::Host* host = zone->create_host("node-" + std::to_string(address), speed)->seal();
    hosts[address] = host;
    return std::make_pair(host->get_netpoint(), nullptr);
  };
  // A node sending to itself (never done by the node programs) needs a route too.
  auto make_loopback = [](s4u::NetZone* zone, const std::vector<unsigned long>&, unsigned long id) {
    return zone->create_link("loopback-" + std::to_string(id), 1e15)->set_latency(0)->seal();
  };
  const std::vector<unsigned long> dimensions(std::size_t(config.dimension), 2);
  s4u::ClusterCallbacks callbacks(make_node, make_loopback, {});
  s4u::NetZone* zone = nullptr;
  if (config.dimension == 0) {
    // A single node: no links at all.
    zone = s4u::create_full_zone("ncube");
    hosts[0] = zone->create_host("node-0", speed)->seal();
  } else {
    zone = s4u::create_torus_zone("ncube", nullptr, dimensions, callbacks, config.link_bandwidth,
                                  config.hop_latency, s4u::Link::SharingPolicy::SPLITDUPLEX);
  }
  announce_platform_built();
  zone->seal();
  return hosts;
}

int hypercube_hops(int from, int to) { return int(std::bitset<32>(unsigned(from ^ to)).count()); }

}  // namespace ncube

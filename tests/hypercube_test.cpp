// The modeled nCube2 network: e-cube routes and the latency-plus-bandwidth timing.
// Each TEST starts its own SimGrid Engine, so ctest runs each in its own process.
#include "simulated_machine.h"

#include <gtest/gtest.h>
#include <simgrid/s4u/Actor.hpp>
#include <simgrid/s4u/Comm.hpp>
#include <simgrid/s4u/Link.hpp>
#include <string>
#include <vector>

#include "machine/platform_config.h"

namespace ncube {
namespace {

TEST(Hypercube, HasTwoToTheDimensionNodesNamedByAddress) {
  const PlatformConfig config = SimulatedMachine::ncube2();
  SimulatedMachine net(config);
  ASSERT_EQ(net.hosts.size(), 64u);
  EXPECT_EQ(net.hosts[37]->get_name(), "node-37");
  EXPECT_DOUBLE_EQ(net.hosts[5]->get_speed(), 2.5e6);
}

TEST(Hypercube, RoutesAreECubeWithOneLinkPerDifferingBit) {
  const PlatformConfig config = SimulatedMachine::ncube2();
  SimulatedMachine net(config);
  for (int from = 0; from < 64; ++from)
    for (int to = 0; to < 64; ++to) {
      if (from == to) continue;
      std::vector<simgrid::s4u::Link*> links;
      double latency = 0.0;
      net.hosts[from]->route_to(net.hosts[to], links, &latency);
      const int hops = __builtin_popcount(unsigned(from ^ to));
      ASSERT_EQ(int(links.size()), hops) << from << "->" << to;
      ASSERT_NEAR(latency, hops * config.hop_latency, 1e-15) << from << "->" << to;
    }
  EXPECT_EQ(hypercube_hops(0, 63), 6);
  EXPECT_EQ(hypercube_hops(5, 10), 4);
}

TEST(Hypercube, MessageTakesHopsTimesLatencyPlusSizeOverBandwidth) {
  const PlatformConfig config = SimulatedMachine::ncube2();
  SimulatedMachine net(config);
  struct Case { int from, to; double bytes; double measured; };
  std::vector<Case> cases = {{0, 1, 1, 0},      {0, 63, 1, 0},       {5, 10, 4096, 0},
                             {17, 46, 1e5, 0},  {63, 0, 12, 0},      {32, 33, 1e6, 0}};
  simgrid::s4u::Actor::create("timer", net.hosts[0], [&] {
    for (Case& c : cases) {
      const double start = simgrid::s4u::Engine::get_clock();
      simgrid::s4u::Comm::sendto(net.hosts[c.from], net.hosts[c.to], std::uint64_t(c.bytes));
      c.measured = simgrid::s4u::Engine::get_clock() - start;
    }
  });
  net.engine.run();
  for (const Case& c : cases) {
    const double expected =
        hypercube_hops(c.from, c.to) * config.hop_latency + c.bytes / config.link_bandwidth;
    EXPECT_DOUBLE_EQ(expected, net.transfer(c.from, c.to, c.bytes));
    EXPECT_NEAR(c.measured, expected, 1e-9 * expected) << c.from << "->" << c.to;
  }
}

// The largest nCube2, 13 dimensions (8,192 nodes), from its shipped platform file. Routes of
// hand-picked pairs: the hop counts are worked out by hand from the addresses in binary.
struct Route8192 {
  int from, to, hops;
};

const std::vector<Route8192> kRoutes8192 = {
    {0, 8191, 13},     // 0 0000 0000 0000 -> 1 1111 1111 1111: every bit
    {8191, 0, 13},     // and back
    {0, 4096, 1},      // the top bit only (dimension 12)
    {8191, 8190, 1},   // the bottom bit only (dimension 0)
    {1234, 1106, 1},   // 1234 = 0 0100 1101 0010, 1106 = 0 0100 0101 0010: bit 7
    {2730, 5461, 13},  // 0 1010 1010 1010 -> 1 0101 0101 0101: alternating bits, all differ
    {4095, 4096, 13},  // 0 1111 1111 1111 -> 1 0000 0000 0000
    {5, 8175, 10},     // 0 0000 0000 0101 -> 1 1111 1110 1111: all but bits 0, 2 and 4
    {3, 6144, 4},      // 0 0000 0000 0011 -> 1 1000 0000 0000: bits 0, 1, 11, 12
};

PlatformConfig largest_ncube2() {
  return load_platform_config(std::string(NCUBE_SOURCE_DIR) + "/platforms/ncube2-d13.json");
}

std::vector<simgrid::s4u::Link*> route(const SimulatedMachine& net, int from, int to,
                                       double* latency = nullptr) {
  std::vector<simgrid::s4u::Link*> links;
  double l = 0.0;
  net.hosts[std::size_t(from)]->route_to(net.hosts[std::size_t(to)], links, &l);
  if (latency) *latency = l;
  return links;
}

TEST(Hypercube8192, HandPickedRoutesHaveTheirHopCountAndLatency) {
  const PlatformConfig config = largest_ncube2();
  SimulatedMachine net(config);
  ASSERT_EQ(net.hosts.size(), 8192u);
  EXPECT_EQ(net.hosts[8191]->get_name(), "node-8191");
  for (const Route8192& r : kRoutes8192) {
    double latency = 0.0;
    EXPECT_EQ(int(route(net, r.from, r.to, &latency).size()), r.hops) << r.from << "->" << r.to;
    EXPECT_NEAR(latency, r.hops * 1e-6, 1e-15) << r.from << "->" << r.to;
    EXPECT_EQ(hypercube_hops(r.from, r.to), r.hops) << r.from << "->" << r.to;
  }
}

// E-cube: the route corrects the differing address bits from bit 0 upwards, so its k-th link
// is the one link between the node reached so far and that node with its lowest remaining
// differing bit flipped.
void expect_ecube_route(const SimulatedMachine& net, int from, int to) {
  const auto links = route(net, from, to);
  int at = from;
  for (std::size_t k = 0; k < links.size() && at != to; ++k) {
    const int bit = (at ^ to) & -(at ^ to);  // lowest differing bit
    const auto hop = route(net, at, at ^ bit);
    ASSERT_EQ(hop.size(), 1u);
    EXPECT_EQ(links[k], hop[0]) << from << "->" << to << ", hop " << k << " from " << at;
    at ^= bit;
  }
  EXPECT_EQ(at, to) << from << "->" << to;
}

TEST(Hypercube, RoutesCorrectTheLowestDifferingBitFirst) {
  SimulatedMachine net;
  for (int from = 0; from < 64; ++from)
    for (int to = 0; to < 64; ++to)
      if (from != to) expect_ecube_route(net, from, to);
}

TEST(Hypercube8192, RoutesCorrectTheLowestDifferingBitFirst) {
  SimulatedMachine net(largest_ncube2());
  for (const Route8192& r : kRoutes8192) expect_ecube_route(net, r.from, r.to);
}

TEST(Hypercube8192, MessageAcrossTheCubeTakesThirteenHopLatencies) {
  const PlatformConfig config = largest_ncube2();
  SimulatedMachine net(config);
  struct Case { int from, to; double bytes, expected, measured; };
  // 13 hops x 1 us + 1e5 B / 2.2e6 B/s; 1 hop x 1 us + 4096 B / 2.2e6 B/s.
  std::vector<Case> cases = {{0, 8191, 1e5, 13e-6 + 1e5 / 2.2e6, 0.0},
                             {4096, 0, 4096, 1e-6 + 4096 / 2.2e6, 0.0}};
  simgrid::s4u::Actor::create("timer", net.hosts[0], [&] {
    for (Case& c : cases) {
      const double start = simgrid::s4u::Engine::get_clock();
      simgrid::s4u::Comm::sendto(net.hosts[std::size_t(c.from)], net.hosts[std::size_t(c.to)],
                                 std::uint64_t(c.bytes));
      c.measured = simgrid::s4u::Engine::get_clock() - start;
    }
  });
  net.engine.run();
  for (const Case& c : cases)
    EXPECT_NEAR(c.measured, c.expected, 1e-9 * c.expected) << c.from << "->" << c.to;
}

}  // namespace
}  // namespace ncube

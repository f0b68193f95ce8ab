// The modeled nCube2 network: e-cube routes and the latency-plus-bandwidth timing.
// Each TEST starts its own SimGrid Engine, so ctest runs each in its own process.
#include "simulated_machine.h"

#include <gtest/gtest.h>
#include <simgrid/s4u/Actor.hpp>
#include <simgrid/s4u/Comm.hpp>
#include <simgrid/s4u/Link.hpp>

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

}  // namespace
}  // namespace ncube

// The network benchmark (src/tools/network_benchmark.h, network_routes.h) on the nCube2,
// against closed forms worked out by hand from platforms/ncube2.json: 80 us of send and 80 us
// of receive overhead, 1 us a hop, 2.2e6 bytes/s a link, e-cube routes over the differing
// address bits, and cost_model.json's 8-byte header on every message. Both forms of the
// platform file (JSON and SimGrid XML) must give the same figures.
#include "tools/network_benchmark.h"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include <simgrid/s4u/Engine.hpp>

#include "machine/cost_model.h"
#include "machine/platform_config.h"
#include "simulation/simulated_platform.h"
#include "tools/network_routes.h"

namespace ncube {
namespace {

const std::string kRoot = NCUBE_SOURCE_DIR;

struct Bench {
  PlatformConfig platform;
  CostModel costs = load_cost_model(kRoot + "/platforms/cost_model.json");
  std::vector<simgrid::s4u::Host*> nodes;
  explicit Bench(const std::string& file)
      : platform(load_platform_config(kRoot + "/platforms/" + file)),
        nodes(build_simulated_platform(platform, {})) {}
};

// Relative 1e-9: SimGrid's sums of latency and transfer times agree with the closed forms to
// about 1e-12; the hand-worked figures below carry 10 or more digits.
#define EXPECT_SECONDS(actual, expected) EXPECT_NEAR(actual, expected, 1e-9 * (expected))

void check_routes(const Bench& bench) {
  const NodeRoute near = nearest_to_node0(bench.nodes);
  EXPECT_EQ(near.from, 0);
  EXPECT_EQ(near.to, 1);  // 1 hop: nodes 1, 2, 4, ... 32 tie; the lowest is taken
  EXPECT_EQ(near.links, 1);
  EXPECT_SECONDS(near.latency, 1e-6);
  EXPECT_DOUBLE_EQ(near.bottleneck_bandwidth, 2.2e6);
  const NodeRoute far = farthest_pair(bench.nodes);
  EXPECT_EQ(far.from, 0);
  EXPECT_EQ(far.to, 63);  // all 6 address bits differ: 6 hops
  EXPECT_EQ(far.links, 6);
  EXPECT_SECONDS(far.latency, 6e-6);
  EXPECT_DOUBLE_EQ(far.bottleneck_bandwidth, 2.2e6);
  EXPECT_EQ(node_route(bench.nodes, 5, 6).links, 2);  // 101 -> 110: two bits
}

// One-way (half a round trip): 80 + 80 us of overheads, hops x 1 us, (payload + 8) / 2.2 us.
void check_ping_pong(const Bench& bench) {
  NetworkBenchmarkSettings settings;
  settings.sizes = {8, 128, 4096, 1048576};
  settings.round_trips = 3;
  settings.stream_messages = 1;
  const PairMeasure near =
      measure_pair("neighbours", nearest_to_node0(bench.nodes), bench.nodes, bench.platform, bench.costs, settings);
  const PairMeasure far =
      measure_pair("farthest", farthest_pair(bench.nodes), bench.nodes, bench.platform, bench.costs, settings);
  ASSERT_EQ(near.sizes.size(), 4u);
  ASSERT_EQ(far.sizes.size(), 4u);
  // wire bytes 16, 136, 4104, 1048584: / 2.2e6 = 7.2727273, 61.8181818, 1865.4545455,
  // 476629.0909091 us
  const double near_us[] = {168.2727273, 222.8181818, 2026.4545455, 476790.0909091};
  const double far_us[] = {173.2727273, 227.8181818, 2031.4545455, 476795.0909091};
  const double wire[] = {16, 136, 4104, 1048584};
  for (std::size_t i = 0; i < 4; ++i) {
    SCOPED_TRACE(near.sizes[i].bytes);
    EXPECT_EQ(near.sizes[i].wire_bytes, wire[i]);  // as the node runtime counted them
    EXPECT_EQ(far.sizes[i].wire_bytes, wire[i]);
    EXPECT_SECONDS(near.sizes[i].one_way_seconds, near_us[i] * 1e-6);
    EXPECT_SECONDS(far.sizes[i].one_way_seconds, far_us[i] * 1e-6);
  }
}

// Ten messages back to back. While a message's wire time is below the 80 us send overhead
// (payload up to 168 bytes), messages never share a link: the sender's overheads pace them,
// and the last one arrives one transfer after the tenth send, then pays the receive overhead:
// 10 x 80 + hops x 1 + wire / 2.2 + 80 us. Above, the link is busy from the first message's
// start to the last's end, 80 + hops x 1 + 10 x wire / 2.2 us, and messages sharing it fairly
// arrive close together: the receiver then still pays one overhead for each of up to ten.
void check_stream(const Bench& bench) {
  NetworkBenchmarkSettings settings;
  settings.sizes = {8, 128, 4096, 1048576};
  settings.round_trips = 1;
  settings.stream_messages = 10;
  for (const NodeRoute& route : {nearest_to_node0(bench.nodes), farthest_pair(bench.nodes)}) {
    const PairMeasure pair = measure_pair("pair", route, bench.nodes, bench.platform, bench.costs, settings);
    const double hops = route.links;
    SCOPED_TRACE(hops);
    EXPECT_SECONDS(pair.sizes[0].stream_seconds, (887.2727273 + hops) * 1e-6);  // 800 + 7.27 + 80
    EXPECT_SECONDS(pair.sizes[1].stream_seconds, (941.8181818 + hops) * 1e-6);  // 800 + 61.82 + 80
    EXPECT_DOUBLE_EQ(pair.sizes[0].stream_bandwidth, 10 * 8 / pair.sizes[0].stream_seconds);
    const double link_busy_us[] = {18654.545455, 4766290.909091};  // 10 x 4104 / 2.2, 10 x 1048584 / 2.2
    for (std::size_t i = 0; i < 2; ++i) {
      const double last_arrival = (80 + hops + link_busy_us[i]) * 1e-6;
      EXPECT_GE(pair.sizes[2 + i].stream_seconds, last_arrival + 80e-6 * (1 - 1e-9));
      EXPECT_LE(pair.sizes[2 + i].stream_seconds, last_arrival + 10 * 80e-6 * (1 + 1e-9));
    }
    // 10 MB in 4.7672 s at most: within 0.02 % of the link's 2.2e6 bytes/s.
    EXPECT_NEAR(pair.sizes[3].stream_bandwidth, 2.2e6, 2.2e6 * 2e-4);
  }
}

TEST(NetworkBenchmark, NcubeJsonRoutesAreTheHypercubes) { check_routes(Bench("ncube2.json")); }
TEST(NetworkBenchmark, NcubeXmlRoutesAreTheHypercubes) { check_routes(Bench("ncube2.xml")); }
TEST(NetworkBenchmark, NcubeJsonPingPongIsOverheadsHopsAndBytes) { check_ping_pong(Bench("ncube2.json")); }
TEST(NetworkBenchmark, NcubeXmlPingPongIsOverheadsHopsAndBytes) { check_ping_pong(Bench("ncube2.xml")); }
TEST(NetworkBenchmark, NcubeJsonStreamIsPacedByOverheadsThenByTheLink) { check_stream(Bench("ncube2.json")); }
TEST(NetworkBenchmark, NcubeXmlStreamIsPacedByOverheadsThenByTheLink) { check_stream(Bench("ncube2.xml")); }

TEST(NetworkBenchmark, MessageCarriesItsPayloadAsTheNodeProgramsCountIt) {
  const CostModel costs = load_cost_model(kRoot + "/platforms/cost_model.json");
  EXPECT_EQ(payload_bytes(*benchmark_message(8), costs), 8);
  EXPECT_EQ(payload_bytes(*benchmark_message(1048576), costs), 1048576);
}

// The pair choice's tie-breaks, on a made-up platform of 4 nodes whose routes tie on latency:
// 0-1 (link a: 0.9 us, 1 link, 1 MB/s), 0-2 (b, c: 0.2 + 0.7 us, 2 links), 0-3 (d: 0.9 us,
// 1 link, 0.1 MB/s); 1-2 (a, b, c: 1.8 us, 3 links, 1 MB/s), 1-3 (a, d: 1.8 us, 2 links),
// 2-3 (b, c, d: 1.8 us, 3 links, 0.1 MB/s). Summed in route order, 1-2's latency comes out
// 1.8000000000000001e-06 and 2-3's 1.8e-06: a tie all the same.
TEST(NetworkBenchmark, PairsBreakLatencyTiesByLinksThenBottleneck) {
  const std::string file = ::testing::TempDir() + "/network_pairs_test.xml";
  {
    std::ofstream xml(file);
    xml << R"(<?xml version='1.0'?>
<!DOCTYPE platform SYSTEM "https://simgrid.org/simgrid.dtd">
<platform version="4.1">
  <zone id="test" routing="Full">
    <host id="node-0" speed="1f"/><host id="node-1" speed="1f"/>
    <host id="node-2" speed="1f"/><host id="node-3" speed="1f"/>
    <link id="a" bandwidth="1MBps" latency="9e-07"/>
    <link id="b" bandwidth="1MBps" latency="2e-07"/>
    <link id="c" bandwidth="1MBps" latency="7e-07"/>
    <link id="d" bandwidth="0.1MBps" latency="9e-07"/>
    <route src="node-0" dst="node-1"><link_ctn id="a"/></route>
    <route src="node-0" dst="node-2"><link_ctn id="b"/><link_ctn id="c"/></route>
    <route src="node-0" dst="node-3"><link_ctn id="d"/></route>
    <route src="node-1" dst="node-2"><link_ctn id="a"/><link_ctn id="b"/><link_ctn id="c"/></route>
    <route src="node-1" dst="node-3"><link_ctn id="a"/><link_ctn id="d"/></route>
    <route src="node-2" dst="node-3"><link_ctn id="b"/><link_ctn id="c"/><link_ctn id="d"/></route>
  </zone>
</platform>
)";
  }
  int argc = 1;
  char name[] = "test";
  char* argv[] = {name, nullptr};
  simgrid::s4u::Engine engine(&argc, argv);
  engine.load_platform(file);
  engine.seal_platform();
  std::vector<simgrid::s4u::Host*> nodes;
  for (int k = 0; k < 4; ++k) nodes.push_back(engine.host_by_name("node-" + std::to_string(k)));
  const NodeRoute near = nearest_to_node0(nodes);
  EXPECT_EQ(near.to, 1);  // 0.9 us each: fewer links than node 2, wider than node 3
  EXPECT_EQ(near.links, 1);
  EXPECT_SECONDS(near.latency, 0.9e-6);
  const NodeRoute far = farthest_pair(nodes);
  EXPECT_EQ(far.from, 2);  // 1.8 us each: more links than 1-3, narrower than 1-2
  EXPECT_EQ(far.to, 3);
  EXPECT_EQ(far.links, 3);
  EXPECT_SECONDS(far.latency, 1.8e-6);
  EXPECT_DOUBLE_EQ(far.bottleneck_bandwidth, 0.1e6);
}

}  // namespace
}  // namespace ncube

// Communication costs of the node programs, against closed forms. Each TEST starts its own
// SimGrid Engine (its own process under ctest).
#include "nodes/collectives.h"

#include <deque>
#include <gtest/gtest.h>
#include <simgrid/s4u/Actor.hpp>
#include <simgrid/s4u/Engine.hpp>

#include "simulated_machine.h"

namespace ncube {
namespace {

struct Machine : SimulatedMachine {
  CostModel costs;
  Machine() {
    costs.message_header_bytes = 8;
    costs.shooter_record_bytes = 88;
    costs.point_bytes = 16;
    costs.flops_per_shooter_candidate = 4;
  }
};

TEST(MessageCost, OneMessageTakesBothOverheadsPlusLatencyAndTransfer) {
  Machine m;
  const std::vector<std::pair<int, int>> pairs = {{0, 1}, {0, 63}, {12, 50}, {7, 56}};
  std::deque<NodeRuntime> runtimes;
  std::vector<double> arrived(pairs.size(), 0.0);
  const double payload = 1600.0;  // a block of 100 points of 16 bytes
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    auto [from, to] = pairs[k];
    NodeRuntime& sender = runtimes.emplace_back(from, NodeRole::kRadiosity, 0, m.platform, m.costs, nullptr);
    NodeRuntime& receiver = runtimes.emplace_back(to, NodeRole::kVisibility, 0, m.platform, m.costs, nullptr);
    // One pair at a time (each starts when the previous is done) so links are not shared.
    const double start = 0.01 * double(k);
    simgrid::s4u::Actor::create("send", m.hosts[from], [&sender, to, start] {
      sender.start();
      simgrid::s4u::this_actor::sleep_until(start);
      auto message = std::make_unique<Message>();
      message->kind = MessageKind::kPoints;
      message->points.resize(100);
      sender.send(to, std::move(message));
      sender.finish();
    });
    simgrid::s4u::Actor::create("receive", m.hosts[to], [&receiver, &arrived, k, start] {
      receiver.start();
      receiver.receive({MessageKind::kPoints});
      arrived[k] = receiver.now() - start;  // the node's time: its charged overhead has run
      receiver.finish();
    });
  }
  m.engine.run();
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    auto [from, to] = pairs[k];
    const double expected = m.platform.send_overhead +
                            m.transfer(from, to, payload + m.costs.message_header_bytes) +
                            m.platform.receive_overhead;
    EXPECT_NEAR(arrived[k], expected, 1e-12) << from << "->" << to;
  }
  EXPECT_EQ(runtimes[0].stats().messages_sent, 1);
  EXPECT_DOUBLE_EQ(runtimes[0].stats().bytes_sent, payload + 8);
}

TEST(MessageCost, ShooterSelectionOver64NodesTakesTheBinomialTreeTime) {
  // 64 radiosity processors (R=64, V=0), all offering a candidate at time 0. Binomial tree:
  // log2(64) = 6 levels up, each one message (both overheads, one hop, the record) and one
  // comparison; 6 levels down, each one message; the deepest leaf gets the decision last.
  Machine m;
  const Placement placement{64, 0};
  std::deque<NodeRuntime> runtimes;
  std::vector<double> done(64, 0.0);
  std::vector<int> decided(64, -1);
  for (int rank = 0; rank < 64; ++rank) {
    NodeRuntime& runtime = runtimes.emplace_back(rank, NodeRole::kRadiosity, rank, m.platform, m.costs, nullptr);
    simgrid::s4u::Actor::create("rp", m.hosts[rank], [&, rank] {
      runtime.start();
      ShooterSelection selection(runtime, placement, rank);
      ShooterChoice mine{rank, double((rank * 37) % 64), Rgb(1.0)};  // rank 19 has power 63 (19 x 37 = 11 x 64 + 63)
      std::vector<ProcessorLoad> loads;
      const ShooterChoice best = selection.reduce_to_master(mine, loads);
      decided[rank] = selection.broadcast_from_master(Decision{best, {}, false}).shooter.patch;
      done[rank] = runtime.now();
      runtime.finish();
    });
  }
  m.engine.run();
  const double bytes = m.costs.shooter_record_bytes + m.costs.message_header_bytes;
  const double step = m.platform.send_overhead + m.transfer(0, 1, bytes) + m.platform.receive_overhead;
  const double compare = m.costs.flops_per_shooter_candidate / m.platform.node_speed;
  const double expected = 6 * (step + compare) + 6 * step;
  EXPECT_NEAR(*std::max_element(done.begin(), done.end()), expected, 1e-12);
  EXPECT_NEAR(done[63], expected, 1e-12);  // the leaf at the end of the longest path
  for (int rank = 0; rank < 64; ++rank) EXPECT_EQ(decided[rank], 19);
}

}  // namespace
}  // namespace ncube

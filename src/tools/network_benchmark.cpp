#include "tools/network_benchmark.h"

#include <functional>
#include <stdexcept>

#include <simgrid/s4u/Actor.hpp>
#include <simgrid/s4u/Engine.hpp>

#include "nodes/node_runtime.h"

namespace ncube {
namespace {

constexpr int kMaskParts = 64;  // 8 bytes a mask (part_mask_bytes)

// Runs two node programs, one on each node of the route, to their end; each gets its own
// NodeRuntime. Throws if either was left blocked.
void run_two(const std::vector<simgrid::s4u::Host*>& nodes, const NodeRoute& route,
             const PlatformConfig& platform, const CostModel& costs,
             const std::function<void(NodeRuntime&)>& first,
             const std::function<void(NodeRuntime&)>& second, double& wire_bytes) {
  NodeRuntime a(route.from, NodeRole::kRadiosity, 0, platform, costs, nullptr);
  NodeRuntime b(route.to, NodeRole::kRadiosity, 0, platform, costs, nullptr);
  for (auto [runtime, program] : {std::make_pair(&a, &first), std::make_pair(&b, &second)}) {
    simgrid::s4u::Actor::create("bench-node-" + std::to_string(runtime->stats().node),
                                nodes.at(std::size_t(runtime->stats().node)),
                                [runtime = runtime, program = program] {
                                  runtime->start();
                                  (*program)(*runtime);
                                  runtime->finish();
                                });
  }
  simgrid::s4u::Engine::get_instance()->run();
  if (!a.finished() || !b.finished())
    throw std::runtime_error("network benchmark: node " +
                             std::to_string(a.finished() ? route.to : route.from) +
                             " did not finish its test");
  // The bytes of one message as the runtime counted them (every message of a test is alike).
  wire_bytes = a.stats().messages_sent > 0 ? a.stats().bytes_sent / double(a.stats().messages_sent)
                                           : b.stats().bytes_sent / double(b.stats().messages_sent);
}

double ping_pong(const std::vector<simgrid::s4u::Host*>& nodes, const NodeRoute& route,
                 const PlatformConfig& platform, const CostModel& costs, double bytes,
                 int round_trips, double& wire_bytes) {
  double start = 0.0, end = 0.0;
  run_two(
      nodes, route, platform, costs,
      [&](NodeRuntime& self) {
        start = self.now();
        for (int trip = 0; trip < round_trips; ++trip) {
          self.send(route.to, benchmark_message(bytes));
          self.receive({MessageKind::kAnswers});
        }
        end = self.now();  // the last receive's overhead paid
      },
      [&](NodeRuntime& self) {
        for (int trip = 0; trip < round_trips; ++trip) {
          self.receive({MessageKind::kAnswers});
          self.send(route.from, benchmark_message(bytes));
        }
      },
      wire_bytes);
  return (end - start) / (2.0 * round_trips);
}

double stream(const std::vector<simgrid::s4u::Host*>& nodes, const NodeRoute& route,
              const PlatformConfig& platform, const CostModel& costs, double bytes, int messages) {
  double start = 0.0, end = 0.0, wire_bytes = 0.0;
  run_two(
      nodes, route, platform, costs,
      [&](NodeRuntime& self) {
        start = self.now();
        for (int m = 0; m < messages; ++m) self.send(route.to, benchmark_message(bytes));
      },
      [&](NodeRuntime& self) {
        for (int m = 0; m < messages; ++m) self.receive({MessageKind::kAnswers});
        end = self.now();  // the last receive's overhead paid
      },
      wire_bytes);
  return end - start;
}

}  // namespace

std::unique_ptr<Message> benchmark_message(double bytes) {
  auto message = std::make_unique<Message>();
  message->kind = MessageKind::kAnswers;
  message->mask_parts = kMaskParts;
  message->masks.assign(std::size_t(bytes / part_mask_bytes(kMaskParts)), PartMask(0));
  return message;
}

PairMeasure measure_pair(const std::string& name, const NodeRoute& route,
                         const std::vector<simgrid::s4u::Host*>& nodes,
                         const PlatformConfig& platform, const CostModel& costs,
                         const NetworkBenchmarkSettings& settings) {
  PairMeasure pair;
  pair.name = name;
  pair.route = route;
  for (double bytes : settings.sizes) {
    SizeMeasure size;
    size.bytes = bytes;
    size.one_way_seconds =
        ping_pong(nodes, route, platform, costs, bytes, settings.round_trips, size.wire_bytes);
    size.stream_seconds = stream(nodes, route, platform, costs, bytes, settings.stream_messages);
    size.stream_bandwidth = settings.stream_messages * bytes / size.stream_seconds;
    pair.sizes.push_back(size);
  }
  return pair;
}

}  // namespace ncube

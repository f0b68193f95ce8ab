// A ping-pong and a streaming-bandwidth benchmark between two nodes of any platform, run
// through the node programs' own runtime (nodes/node_runtime.h): each message pays the
// sender's and the receiver's software overhead as CPU time and carries its payload plus the
// message header over the platform's route, counted as the node programs count theirs
// (nodes/messages.h). What it measures is therefore what the radiosity program's messages
// cost on that machine (docs/network-benchmark.md).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <simgrid/forward.h>

#include "machine/cost_model.h"
#include "machine/platform_config.h"
#include "nodes/messages.h"
#include "tools/network_routes.h"

namespace ncube {

struct NetworkBenchmarkSettings {
  std::vector<double> sizes;  // payload bytes per message, each a positive multiple of 8
  int round_trips = 4;        // ping-pong: round trips timed together
  int stream_messages = 32;   // streaming: messages sent back to back
};

struct SizeMeasure {
  double bytes = 0.0;             // payload of one message
  double wire_bytes = 0.0;        // what the runtime put on the network: payload and header
  double one_way_seconds = 0.0;   // ping-pong: half the mean round trip
  double stream_seconds = 0.0;    // streaming: first send begun to the last message taken,
                                  // its receive overhead paid
  double stream_bandwidth = 0.0;  // streaming: payload bytes per second
};

struct PairMeasure {
  std::string name;  // "neighbours", "farthest"
  NodeRoute route;
  std::vector<SizeMeasure> sizes;
};

// A message of `bytes` of payload: a visibility processor's block of answers (kAnswers),
// bytes / 8 part masks of 64 parts, which payload_bytes counts at 8 bytes each.
std::unique_ptr<Message> benchmark_message(double bytes);

// Ping-pong and streaming at every size, from route.from to route.to, one after the other
// (each test alone on the network). `nodes` are the platform's hosts in node order, in the
// process's Engine; each test is one Engine::run. Throws std::runtime_error if a node of a
// test does not finish.
PairMeasure measure_pair(const std::string& name, const NodeRoute& route,
                         const std::vector<simgrid::s4u::Host*>& nodes,
                         const PlatformConfig& platform, const CostModel& costs,
                         const NetworkBenchmarkSettings& settings);

}  // namespace ncube

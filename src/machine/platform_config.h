// The modeled machine, read from platforms/<machine>.json (e.g. platforms/ncube2.json).
#pragma once

#include <string>

namespace ncube {

struct PlatformConfig {
  int dimension = 6;                  // hypercube dimension: 2^dimension nodes
  double node_speed = 2.5e6;          // flop/s of one node
  double node_memory = 4194304;       // bytes of one node
  double link_bandwidth = 2.2e6;      // bytes/s per direction of one link
  double hop_latency = 1e-6;          // s per hop of a route
  double send_overhead = 80e-6;       // CPU s of the sender per message
  double receive_overhead = 80e-6;    // CPU s of the receiver per message

  int node_count() const { return 1 << dimension; }
};

PlatformConfig load_platform_config(const std::string& path);

}  // namespace ncube

// The modeled machine, read from platforms/<machine>.json (e.g. platforms/ncube2.json).
// The values live in that file only (one source): a default-constructed PlatformConfig is
// an empty machine, never the nCube2.
#pragma once

#include <string>

namespace ncube {

struct PlatformConfig {
  int dimension = 0;              // hypercube dimension: 2^dimension nodes
  double node_speed = 0.0;        // flop/s of one node
  double node_memory = 0.0;       // bytes of one node
  double link_bandwidth = 0.0;    // bytes/s per direction of one link
  double hop_latency = 0.0;       // s per hop of a route
  double send_overhead = 0.0;     // CPU s of the sender per message
  double receive_overhead = 0.0;  // CPU s of the receiver per message

  int node_count() const { return 1 << dimension; }
};

PlatformConfig load_platform_config(const std::string& path);

}  // namespace ncube

#include "machine/platform_config.h"

#include "machine/parameter_file.h"

namespace ncube {

PlatformConfig load_platform_config(const std::string& path) {
  // Sanity bounds, far around the nCube2's values: within them every simulated time stays
  // finite and well inside the range SimGrid computes with (docs/model.md, "Machine").
  const auto v = read_parameter_file(path, {{"dimension", 0, true, 13},
                                            {"node_speed", 1e3, false, 1e15},
                                            {"node_memory", 1, true, 0x1p50},
                                            {"link_bandwidth", 1e3, false, 1e15},
                                            {"hop_latency", 0, false, 1},
                                            {"send_overhead", 0, false, 1},
                                            {"receive_overhead", 0, false, 1}});
  PlatformConfig c;
  c.dimension = int(v.at("dimension"));
  c.node_speed = v.at("node_speed");
  c.node_memory = v.at("node_memory");
  c.link_bandwidth = v.at("link_bandwidth");
  c.hop_latency = v.at("hop_latency");
  c.send_overhead = v.at("send_overhead");
  c.receive_overhead = v.at("receive_overhead");
  return c;
}

}  // namespace ncube

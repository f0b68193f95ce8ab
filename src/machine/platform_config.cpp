#include "machine/platform_config.h"

#include "machine/parameter_file.h"

namespace ncube {

PlatformConfig load_platform_config(const std::string& path) {
  const auto v = read_parameter_file(path, {{"dimension", 0, true, 13},
                                            {"node_speed", 1e-300, false},
                                            {"node_memory", 1, true},
                                            {"link_bandwidth", 1e-300, false},
                                            {"hop_latency", 0, false},
                                            {"send_overhead", 0, false},
                                            {"receive_overhead", 0, false}});
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

// Test fixture: a SimGrid Engine with the nCube2 hypercube built from a platform config
// (by default platforms/ncube2.json, the one source of the machine's values).
// One per TEST (SimGrid allows one Engine per process; ctest runs each TEST on its own).
#pragma once

#include <simgrid/s4u/Engine.hpp>
#include <string>
#include <vector>

#include "machine/hypercube.h"
#include "machine/simgrid_session.h"
#include "machine/platform_config.h"

namespace ncube {

struct SimulatedMachine {
  int argc = 1;
  char name[8] = "test";
  char* argv[2] = {name, nullptr};
  simgrid::s4u::Engine engine{&argc, argv};
  PlatformConfig platform;
  std::vector<simgrid::s4u::Host*> hosts;

  static PlatformConfig ncube2() {
    return load_platform_config(std::string(NCUBE_SOURCE_DIR) + "/platforms/ncube2.json");
  }
  explicit SimulatedMachine(const PlatformConfig& config = ncube2()) : platform(config) {
    apply_simgrid_defaults(platform.simgrid_config);
    hosts = build_hypercube(platform);
  }
  // h x latency + S / bandwidth: one message alone on its e-cube route.
  double transfer(int from, int to, double bytes) const {
    return hypercube_hops(from, to) * platform.hop_latency + bytes / platform.link_bandwidth;
  }
};

}  // namespace ncube

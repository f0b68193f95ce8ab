// What SimGrid alone needs for a machine of the project's platforms: the platform built as a
// run builds it (build_simulated_platform, with the platform's SimGrid settings), one actor
// per node, and one message passed around the ring of them, with none of the node programs.
// It prints host seconds and peak resident memory, the floor beside a run of ./simulate on
// the same platform (docs/performance-log.md, "8,192 nodes"). A reported benchmark, not a test:
//
//   build/simgrid_alone platforms/ncube2-d13.json [ACTORS]    (default: one per node)
#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <simgrid/s4u/Actor.hpp>
#include <simgrid/s4u/Engine.hpp>
#include <simgrid/s4u/Mailbox.hpp>

#include "machine/platform_config.h"
#include "simulation/simulated_platform.h"

namespace {

double peak_mib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / 1024.0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: simgrid_alone PLATFORM.json [ACTORS]\n");
    return 2;
  }
  const auto start = std::chrono::steady_clock::now();
  const ncube::PlatformConfig platform = ncube::load_platform_config(argv[1]);
  const std::vector<simgrid::s4u::Host*> hosts = ncube::build_simulated_platform(platform, {});
  const double platform_mib = peak_mib();
  const int actors = argc > 2 ? std::atoi(argv[2]) : int(hosts.size());
  static int token = 0;
  for (int a = 0; a < actors; ++a)
    simgrid::s4u::Actor::create("node-" + std::to_string(a), hosts[std::size_t(a) % hosts.size()], [a, actors] {
      simgrid::s4u::this_actor::execute(1e3);
      simgrid::s4u::Mailbox* mine = simgrid::s4u::Mailbox::by_name("ring-" + std::to_string(a));
      simgrid::s4u::Mailbox* next = simgrid::s4u::Mailbox::by_name("ring-" + std::to_string((a + 1) % actors));
      if (a == 0) next->put(&token, 64);
      mine->get<int>();
      if (a != 0) next->put(&token, 64);
    });
  simgrid::s4u::Engine::get_instance()->run();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("%zu nodes, %d actors: %.2f host s, peak %.0f MiB (%.0f MiB after the platform)\n",
              hosts.size(), actors, seconds, peak_mib(), platform_mib);
  return 0;
}

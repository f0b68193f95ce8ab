// What SimGrid alone needs for the same messages as a run: the run's activity record
// (NCUBE_RECORD_ACTIVITIES=FILE ./simulate ..., src/nodes/activity_record.h) replayed on the
// platform built as the run builds it, one actor per node in the run's order, each doing its
// node's executes, puts and gets in the node's order, with no node program, no radiosity
// and no visibility behind them. The replay ends at the run's simulated time (printed, so
// that tests/simgrid_replay_test.sh can hold it to the run's); its host and CPU seconds are
// SimGrid's floor beside the run (bench/long_runs.py --simgrid-alone). A reported
// benchmark, not a test:
//
//   NCUBE_RECORD_ACTIVITIES=/tmp/run.act ./simulate scenes/scene3.json --R 8 --V 7 --quiet
//   build/simgrid_replay platforms/ncube2.json /tmp/run.act [--cfg=NAME:VALUE ...]
//
// SimGrid settings after the record are applied as simulate's --cfg is (to try one on the
// run's messages alone: the simulated end shows whether it changes the run's times).
// Exit codes: 2 for bad use, 3 for a record or platform that cannot be read.
#include <sys/resource.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <string>
#include <vector>

#include <simgrid/s4u/Actor.hpp>
#include <simgrid/s4u/Comm.hpp>
#include <simgrid/s4u/Engine.hpp>
#include <simgrid/s4u/Mailbox.hpp>

#include "machine/platform_config.h"
#include "nodes/activity_record.h"
#include "nodes/node_runtime.h"
#include "simulation/simulated_platform.h"

namespace {

double peak_mib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / 1024.0;
}

double cpu_seconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
         1e-6 * double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

template <typename T>
T take(const unsigned char*& at) {
  T value;
  std::memcpy(&value, at, sizeof(T));
  at += sizeof(T);
  return value;
}

struct Totals {
  long executes = 0, puts = 0, gets = 0;
};

// One node's activities, in its order. Every message carries the same dummy payload: the
// replay's receivers only count them.
void replay(const ncube::ActivityRecord::Stream& stream, Totals& totals) {
  static char payload = 0;
  simgrid::s4u::Mailbox* mine = ncube::node_mailbox(stream.node);
  mine->set_receiver(simgrid::s4u::Actor::self());
  const unsigned char* at = stream.bytes.data();
  const unsigned char* end = at + stream.bytes.size();
  while (at < end) {
    switch (*at++) {
      case ncube::ActivityRecord::kExecute:
        simgrid::s4u::this_actor::execute(take<double>(at));
        ++totals.executes;
        break;
      case ncube::ActivityRecord::kPut: {
        const int to = take<std::int32_t>(at);
        const std::uint64_t bytes = take<std::uint64_t>(at);
        ncube::node_mailbox(to)->put_init(&payload, bytes)->detach();
        ++totals.puts;
        break;
      }
      case ncube::ActivityRecord::kGet:
        mine->get<char>();
        ++totals.gets;
        break;
      default:
        std::fprintf(stderr, "simgrid_replay: node %d: unknown activity %d\n", stream.node, int(at[-1]));
        std::exit(3);
    }
  }
  mine->set_receiver(nullptr);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: simgrid_replay PLATFORM.json ACTIVITY_RECORD [--cfg=NAME:VALUE ...]\n");
    return 2;
  }
  ncube::PlatformConfig platform;
  ncube::ActivityRecord record;
  try {
    platform = ncube::load_platform_config(argv[1]);
    record = ncube::ActivityRecord::read(argv[2]);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "simgrid_replay: %s\n", e.what());
    return 3;
  }
  const auto start = std::chrono::steady_clock::now();
  const double cpu_start = cpu_seconds();
  const std::vector<simgrid::s4u::Host*> hosts = ncube::build_simulated_platform(platform, std::vector<std::string>(argv + 3, argv + argc));
  Totals totals;
  for (const ncube::ActivityRecord::Stream& stream : record.streams()) {
    if (stream.node < 0 || std::size_t(stream.node) >= hosts.size()) {
      std::fprintf(stderr, "simgrid_replay: %s: node %d is not on the platform (%zu nodes)\n",
                   argv[2], stream.node, hosts.size());
      return 3;
    }
    simgrid::s4u::Actor::create("node-" + std::to_string(stream.node), hosts[std::size_t(stream.node)],
                                [&stream, &totals] { replay(stream, totals); });
  }
  simgrid::s4u::Engine::get_instance()->run();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("%zu actors, %ld executes, %ld puts, %ld gets: %.2f host s, %.2f CPU s, peak %.0f MiB, "
              "simulated end %.17g s\n",
              record.streams().size(), totals.executes, totals.puts, totals.gets, seconds,
              cpu_seconds() - cpu_start, peak_mib(), simgrid::s4u::Engine::get_clock());
  return 0;
}

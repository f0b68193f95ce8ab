#include "simulation/actor_exceptions.h"

#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <new>
#include <string>
#include <vector>

#include <simgrid/s4u/Actor.hpp>
#include <xbt/config.hpp>

#include "util/input_error.h"

namespace ncube {

namespace {
constexpr std::size_t kReserveBytes = std::size_t(16) << 20;  // not touched: no resident page

// The stacks asked for by check_stacks and not yet handed to SimGrid, one block each: held
// until guard() hands one back for the actor being created with it. What the launch
// allocates in between (the node programs, their engines) fails as a clean bad_alloc then,
// instead of taking the stacks' room: probed and given back at once, a run on 1,024 nodes in
// a window of about 200 MB of ulimit -v ended in SimGrid's "Failed to allocate stack" abort.
using Block = std::unique_ptr<void, decltype(&std::free)>;
std::vector<Block>& reserved_stacks() {
  static std::vector<Block> blocks;
  return blocks;
}
// Room for what the run allocates besides the stacks, held with them and given back with the
// last: the allocations of creating an actor (its name, its SimGrid objects) carve pieces out
// of the stack just handed back, so the stack needs room beside it; and the run on 1,024 nodes
// took about 250 MB of address space more once its actors were created (a limit inside that
// ended in allocation failures in SimGrid's own code, an abort).
// Mapped from the kernel, not malloc's: given back, it is address space any allocator and
// the host threads' stacks can map again (a malloc such as tcmalloc keeps what is freed).
constexpr std::size_t kRoomPerActor = std::size_t(256) << 10;
constexpr std::size_t kRoomAtLeast = std::size_t(64) << 20;
struct Room {
  void* start = nullptr;
  std::size_t bytes = 0;
  explicit operator bool() const { return start != nullptr; }
  void reset(std::size_t wanted = 0) {
    if (start) munmap(start, bytes);
    start = nullptr;
    bytes = wanted;
    if (wanted == 0) return;
    void* mapped = mmap(nullptr, wanted, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (mapped != MAP_FAILED) start = mapped;
  }
};
Room& reserved_room() {
  static Room room;
  return room;
}
// One stack more, in malloc's heap, given back with the first actor: the small allocations
// of creating an actor are cut from it, not from the stack just given back for SimGrid.
Block& spare_stack() {
  static Block spare(nullptr, &std::free);
  return spare;
}

std::string mib(std::size_t bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f", double(bytes) / double(1 << 20));
  return text;
}
}  // namespace

ActorExceptions::ActorExceptions() : reserve_(new char[kReserveBytes]) {}

std::function<void()> ActorExceptions::guard(std::function<void()> body) {
  if (!reserved_stacks().empty()) {
    spare_stack().reset();
    reserved_stacks().pop_back();  // this actor's stack
    if (reserved_stacks().empty()) reserved_room().reset();
  }
  return [this, body = std::move(body)] {
    try {
      body();
    } catch (const std::exception&) {
      reserve_.reset();
      if (!first_) first_ = std::current_exception();
      simgrid::s4u::Actor::kill_all();  // the others would wait forever for this one
    }
  };
}

void ActorExceptions::check_stacks(std::size_t actors) {
  // Each stack: contexts/stack-size KiB and contexts/guard-size pages, allocated by SimGrid
  // through malloc's posix_memalign, which reuses what is freed here (one page more: its
  // alignment).
  const int kib = simgrid::config::get_value<int>("contexts/stack-size");
  const std::size_t stack = std::size_t(kib) * 1024 +
                            std::size_t(simgrid::config::get_value<int>("contexts/guard-size") + 1) *
                                std::size_t(sysconf(_SC_PAGESIZE));
  // One block per stack, as SimGrid allocates them (one block of all would be refused by the
  // kernel's overcommit heuristic on a large platform where the stacks one by one are not).
  auto& blocks = reserved_stacks();
  blocks.clear();
  blocks.reserve(actors);
  const std::size_t room = std::max(kRoomAtLeast, actors * kRoomPerActor);
  reserved_room().reset(room);
  spare_stack().reset(std::malloc(stack));
  for (std::size_t k = 0; k < actors && reserved_room() && spare_stack(); ++k) {
    blocks.emplace_back(std::malloc(stack), &std::free);
    if (!blocks.back()) {
      blocks.clear();
      reserved_room().reset();
      spare_stack().reset();
      throw HostMemoryError(
          "the stacks of the simulation's " + std::to_string(actors) + " actors (" +
          mib(stack) + " MiB each: contexts/stack-size " + std::to_string(kib) +
          " KiB and its guard) do not fit in the host's memory or address space (" +
          std::to_string(k) + " did): a smaller --cfg=contexts/stack-size (at least 1024 KiB), "
          "fewer nodes, or more memory");
    }
  }
  if (!reserved_room() || !spare_stack()) {
    blocks.clear();
    spare_stack().reset();
    throw HostMemoryError("the simulation's " + std::to_string(actors) + " actors need " +
                          mib(room) + " MiB of room besides their stacks, which the host's "
                          "memory or address space does not have: fewer nodes, or more memory");
  }
}

void ActorExceptions::rethrow_first() const {
  if (first_) std::rethrow_exception(first_);
}

}  // namespace ncube

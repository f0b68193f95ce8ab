#include "simulation/actor_stacks.h"

#include <dlfcn.h>
#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <memory>
#include <stdexcept>
#include <utility>
#include <vector>

#include <simgrid/config.h>
#include <simgrid/s4u/Actor.hpp>
#include <xbt/config.hpp>

#include "util/input_error.h"
#include "util/input_file.h"

namespace ncube {
namespace {

// The stack offered to the next posix_memalign of this thread that asks for exactly its size:
// set by create_actor around Actor::create, taken (set to null) by the posix_memalign below.
// Per thread: an allocation on a host thread (Embree, the thread pool) never takes it.
struct Offer {
  void* block = nullptr;
  std::size_t bytes = 0;
};
thread_local Offer offered;

using PosixMemalign = int (*)(void**, std::size_t, std::size_t);
// The posix_memalign every call would reach without the one below (tcmalloc's in ./simulate,
// the C library's elsewhere).
PosixMemalign next_posix_memalign() {
  static const PosixMemalign next =
      reinterpret_cast<PosixMemalign>(dlsym(RTLD_NEXT, "posix_memalign"));
  if (next == nullptr) std::abort();  // no allocator below: cannot happen with a C library
  return next;
}

}  // namespace
}  // namespace ncube

// The process's posix_memalign (defined in the executable, it is the one SimGrid's library
// calls): the offered stack when one is offered on this thread and the call asks for its size,
// else the allocator's own.
extern "C" int posix_memalign(void** block, std::size_t alignment, std::size_t bytes) noexcept {
  ncube::Offer& offer = ncube::offered;
  if (offer.block != nullptr && bytes == offer.bytes && alignment != 0 &&
      reinterpret_cast<std::uintptr_t>(offer.block) % alignment == 0) {
    *block = offer.block;
    offer = {};
    return 0;
  }
  return ncube::next_posix_memalign()(block, alignment, bytes);
}

namespace ncube {
namespace {

using Block = std::unique_ptr<void, decltype(&std::free)>;

// Room for what the run allocates besides the stacks, held with them and given back with the
// last: the node programs built between the reservation and the actors' creation take their
// memory beside it, and the run on 1,024 nodes took about 250 MB of address space more once its
// actors were created (a limit inside that ended in allocation failures in SimGrid's own code,
// an abort). Mapped from the kernel, not malloc's: given back, it is address space any
// allocator and the host threads' stacks can map again (tcmalloc keeps what is freed to it).
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

// What reserve_actor_stacks set aside and create_actor has not handed over yet.
struct Reservation {
  std::vector<Block> stacks;  // one block per actor, as SimGrid allocates them
  std::size_t stack_bytes = 0;
  // Whether SimGrid allocates each stack with posix_memalign(page size, stack_bytes), so that
  // it takes the offered block: its SwappedContext with a guard (3.32 without model checking;
  // the thread factory's stacks are the threads', a guard of 0 pages is a calloc).
  bool handed_over = false;
  std::size_t taken = 0;  // by SimGrid, as offered
  Room room;
};
Reservation& reservation() {
  static Reservation reserved;
  return reserved;
}

// SimGrid turns each stack's guard pages PROT_NONE (mprotect), which splits the memory mapping
// that holds the stack: two mappings per actor, and it aborts ("Failed to protect stack") when
// the kernel's limit on a process's mappings (vm.max_map_count, 65,530 by default) is reached:
// about 32,000 actors with a guard. Room for the mappings the run makes besides (host
// threads' stacks, the allocator's growth; a run on 1,024 nodes had about 250 besides its
// actors' 2,048).
constexpr long kMappingsPerGuardedStack = 2;
constexpr long kMappingsForTheRun = 1024;

// Lines of a kernel's file (the mappings of /proc/self/maps), through the read gate; -1 when it
// cannot be read (the check is then left out, as on a host without /proc).
long count_lines(const char* path) {
  try {
    const std::string text = read_input_file(path, kProcessMapsFile);
    return long(std::count(text.begin(), text.end(), '\n'));
  } catch (const InputError&) {
    return -1;
  }
}

long read_number(const char* path) {
  try {
    std::istringstream text(read_input_file(path, kKernelFile));
    long value = -1;
    if (!(text >> value)) return -1;
    return value;
  } catch (const InputError&) {
    return -1;
  }
}

std::string mib(std::size_t bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f", double(bytes) / double(1 << 20));
  return text;
}

}  // namespace

void reserve_actor_stacks(std::size_t actors) {
  const int kib = simgrid::config::get_value<int>("contexts/stack-size");
  const int guard_pages = simgrid::config::get_value<int>("contexts/guard-size");
  const std::size_t page = std::size_t(sysconf(_SC_PAGESIZE));
  Reservation& reserved = reservation();
  reserved.stacks.clear();
  reserved.taken = 0;
  reserved.stack_bytes = std::size_t(kib) * 1024 + std::size_t(guard_pages) * page;
  // SimGrid's SwappedContext (every factory but the threads) guards the stacks it allocates.
  const bool guarded = guard_pages > 0 &&
                       simgrid::config::get_value<std::string>("contexts/factory") != "thread";
  reserved.handed_over = guarded && !SIMGRID_HAVE_MC;
  const long allowed = read_number("/proc/sys/vm/max_map_count");
  const long in_use = count_lines("/proc/self/maps");
  const long needed = kMappingsPerGuardedStack * long(actors) + kMappingsForTheRun;
  if (guarded && allowed > 0 && in_use >= 0 && in_use + needed > allowed)
    throw HostMemoryError(
        "the guard pages of the stacks of the simulation's " + std::to_string(actors) +
        " actors need about " + std::to_string(needed) + " memory mappings, and the host allows " +
        std::to_string(allowed) + " to a process (vm.max_map_count), " + std::to_string(in_use) +
        " in use: --cfg=contexts/guard-size:0, fewer nodes, or a larger vm.max_map_count");
  const std::size_t room = std::max(kRoomAtLeast, actors * kRoomPerActor);
  reserved.room.reset(room);
  if (!reserved.room)
    throw HostMemoryError("the simulation's " + std::to_string(actors) + " actors need " +
                          mib(room) + " MiB of room besides their stacks, which the host's "
                          "memory or address space does not have: fewer nodes, or more memory");
  // One block per stack, with SimGrid's own call (one block of all would be refused by the
  // kernel's overcommit heuristic on a large platform where the stacks one by one are not).
  reserved.stacks.reserve(actors);
  for (std::size_t k = 0; k < actors; ++k) {
    void* block = nullptr;
    if (posix_memalign(&block, page, reserved.stack_bytes) != 0) {
      reserved.stacks.clear();
      reserved.room.reset();
      throw HostMemoryError(
          "the stacks of the simulation's " + std::to_string(actors) + " actors (" +
          mib(reserved.stack_bytes) + " MiB each: contexts/stack-size " + std::to_string(kib) +
          " KiB and its guard) do not fit in the host's memory or address space (" +
          std::to_string(k) + " did): a smaller --cfg=contexts/stack-size (at least 1024 KiB), "
          "fewer nodes, or more memory");
    }
    reserved.stacks.emplace_back(block, &std::free);
  }
}

void create_actor(const std::string& name, simgrid::s4u::Host* host, std::function<void()> code) {
  Reservation& reserved = reservation();
  if (reserved.stacks.empty()) {
    simgrid::s4u::Actor::create(name, host, std::move(code));
    return;
  }
  Block stack = std::move(reserved.stacks.back());
  reserved.stacks.pop_back();
  if (reserved.stacks.empty()) reserved.room.reset();
  if (!reserved.handed_over) {
    stack.reset();  // given back for SimGrid's own allocation, which takes it if nothing else does
    simgrid::s4u::Actor::create(name, host, std::move(code));
    return;
  }
  offered = {stack.get(), reserved.stack_bytes};
  // Taken: SimGrid owns the block (and frees it with the actor). Not taken: freed here.
  const auto settle = [&stack] {
    const bool taken = offered.block == nullptr;
    offered = {};
    if (taken) static_cast<void>(stack.release());
    return taken;
  };
  try {
    simgrid::s4u::Actor::create(name, host, std::move(code));
  } catch (...) {
    settle();
    throw;
  }
  if (settle()) {
    ++reserved.taken;
    return;
  }
  throw std::logic_error("SimGrid did not take the stack reserved for actor " + name + " (" +
                         std::to_string(reserved.stack_bytes) +
                         " bytes, page-aligned, as SimGrid 3.32 allocates a stack with "
                         "posix_memalign): src/simulation/actor_stacks.cpp must follow how "
                         "this SimGrid allocates stacks");
}

std::size_t actor_stacks_handed_over() { return reservation().taken; }

}  // namespace ncube

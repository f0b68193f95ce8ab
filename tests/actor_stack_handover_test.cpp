// The actors' stacks handed to SimGrid (src/simulation/actor_stacks.h): the block reserved for
// an actor is the one SimGrid's stack allocation takes in Actor::create, and a stack SimGrid
// does not take is an internal error, not a silent give-back. Each TEST starts its own SimGrid
// Engine (its own process under ctest). The address-space limits themselves are exercised by
// tests/actor_stacks_test.sh.
#include "simulation/actor_stacks.h"

#include <sys/mman.h>
#include <unistd.h>

#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <simgrid/s4u/Actor.hpp>
#include <simgrid/s4u/Engine.hpp>
#include <stdexcept>
#include <xbt/config.hpp>

#include "simulated_machine.h"
#include "util/input_error.h"

namespace ncube {
namespace {

// Creates `actors` actors through create_actor after reserving their stacks; each runs once.
int create_and_run(SimulatedMachine& m, int actors) {
  int ran = 0;
  reserve_actor_stacks(std::size_t(actors));
  for (int k = 0; k < actors; ++k)
    create_actor("stack-" + std::to_string(k), m.hosts[std::size_t(k) % m.hosts.size()], [&ran] {
      volatile char on_the_stack[64 * 1024];  // the stack is usable: 64 KiB written
      for (std::size_t i = 0; i < sizeof on_the_stack; ++i) on_the_stack[i] = char(i);
      if (on_the_stack[1000] == char(1000)) ++ran;
    });
  m.engine.run();
  return ran;
}

TEST(ActorStackHandover, SimGridTakesEveryReservedStack) {
  SimulatedMachine m;
  EXPECT_EQ(create_and_run(m, 8), 8);  // create_actor throws if a stack was not taken
  EXPECT_EQ(actor_stacks_handed_over(), 8u);
}

TEST(ActorStackHandover, LargerGuardIsHandedOverToo) {
  SimulatedMachine m;
  simgrid::config::set_value("contexts/guard-size", 4);
  EXPECT_EQ(create_and_run(m, 4), 4);
  EXPECT_EQ(actor_stacks_handed_over(), 4u);
}

TEST(ActorStackHandover, WithoutGuardTheStacksAreGivenBack) {
  SimulatedMachine m;  // SimGrid allocates an unguarded stack with calloc: nothing is offered
  simgrid::config::set_value("contexts/guard-size", 0);
  EXPECT_EQ(create_and_run(m, 4), 4);
  EXPECT_EQ(actor_stacks_handed_over(), 0u);
}

TEST(ActorStackHandover, AStackSimGridDoesNotTakeIsAnInternalError) {
  SimulatedMachine m;
  reserve_actor_stacks(1);
  // SimGrid now asks for stacks of another size than the one reserved and offered.
  simgrid::config::set_value("contexts/stack-size", 4096);
  EXPECT_THROW(create_actor("stack", m.hosts[0], [] {}), std::logic_error);
}

long mappings_in_use() {
  std::ifstream maps("/proc/self/maps");
  long lines = 0;
  for (std::string line; std::getline(maps, line);) ++lines;
  return lines;
}

// SimGrid's guard page splits each stack's mapping in two; past the kernel's limit on a
// process's mappings, SimGrid aborts ("Failed to protect stack"). Brought within 1,500 mappings
// of the limit, 1,000 actors (2,000 mappings and room for the run's own) are refused: created
// there without the check, they ended in that abort (exit 134).
TEST(ActorStackHandover, StacksBeyondTheMappingLimitAreRefused) {
  SimulatedMachine m;
  long allowed = -1;
  std::ifstream("/proc/sys/vm/max_map_count") >> allowed;
  if (allowed <= 0) GTEST_SKIP() << "no /proc/sys/vm/max_map_count";
  const std::size_t page = std::size_t(sysconf(_SC_PAGESIZE));
  // Mappings of one page each: every other page of one region made inaccessible.
  const std::size_t pages = std::size_t(allowed - mappings_in_use() - 1500);
  void* region = mmap(nullptr, pages * page, PROT_READ, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  ASSERT_NE(region, MAP_FAILED);
  for (std::size_t p = 1; p < pages; p += 2)
    ASSERT_EQ(mprotect(static_cast<char*>(region) + p * page, page, PROT_NONE), 0);
  EXPECT_GT(mappings_in_use(), allowed - 1600);
  try {
    reserve_actor_stacks(1000);
    ADD_FAILURE() << "1,000 actors' stacks accepted within 1,500 mappings of the limit";
  } catch (const HostMemoryError& e) {
    EXPECT_NE(std::string(e.what()).find("vm.max_map_count"), std::string::npos) << e.what();
  }
  reserve_actor_stacks(100);  // 200 mappings and the run's own fit
  munmap(region, pages * page);
}

}  // namespace
}  // namespace ncube

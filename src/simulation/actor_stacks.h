// The actors' stacks. SimGrid 3.32 allocates an actor's stack inside Actor::create, with
// posix_memalign(page size, contexts/stack-size KiB + contexts/guard-size pages) (its
// SwappedContext: the raw, boost and ucontext factories), and ends the process when that fails
// (xbt_assert "Failed to allocate stack.", SIGABRT, exit 134) instead of reporting it. Here the
// stacks are reserved before the node programs are built, with that very call, and each actor
// is created with one of them handed to SimGrid as the block its posix_memalign returns: its
// stack cannot fail to be allocated, whatever the run allocated in between. When they do not
// fit, reserve_actor_stacks refuses the run (exit 6, one line with the figures).
//
// Why a hand-over and not a give-back (free, then SimGrid allocates): between the free and
// SimGrid's allocation, Actor::create makes small allocations (the actor, its name, its
// context), and tcmalloc's page heap cuts their pages out of the best-fitting free span, the
// stack just freed (8 MiB + 8 KiB, one page taken leaves 8 MiB: too small); the stack then
// needs fresh address space, which under a limit it may not have. Measured on a shooters run
// on 1,024 nodes under ulimit -v 9.05 GB: the 284th actor's stack failed with one free span of
// 8.0 MiB in the page heap (issue 37; tests/actor_stacks_test.sh).
#pragma once

#include <cstddef>
#include <functional>
#include <string>

#include <simgrid/forward.h>

namespace ncube {

// Throws HostMemoryError (exit 6, one line naming the stacks) when the host cannot hold the
// stacks of `actors` actors and the room the run needs beside them; otherwise reserves them
// (allocated, never touched: address space, not resident memory) for create_actor, dropping
// what an earlier call reserved and did not hand over.
void reserve_actor_stacks(std::size_t actors);

// simgrid::s4u::Actor::create(name, host, code), with one of the stacks reserve_actor_stacks
// reserved as the actor's stack (when there is none left, SimGrid allocates it as usual).
// Throws InternalError (exit 7) if SimGrid did not take the stack it was offered where it
// should have (a SimGrid that allocates stacks otherwise than 3.32: the guarantee would be
// lost silently otherwise).
void create_actor(const std::string& name, simgrid::s4u::Host* host, std::function<void()> code);

// How many of the stacks of the last reserve_actor_stacks SimGrid took as they were offered.
std::size_t actor_stacks_handed_over();

}  // namespace ncube

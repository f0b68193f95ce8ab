// Exceptions thrown inside node programs, carried out of SimGrid. An exception that leaves a
// SimGrid actor ends the process (SimGrid logs it and aborts: exit 134, output temporaries
// left behind), so a host allocation failure during the run (std::bad_alloc) would not be the
// documented exit 6 (docs/cli.md). Each actor's body runs through guard(): the first exception
// is kept, every other actor is killed (their stacks unwind), Engine::run returns, and the
// caller rethrows it, so it reaches main() like any exception outside the run.
#pragma once

#include <cstddef>
#include <exception>
#include <functional>
#include <memory>

namespace ncube {

class ActorExceptions {
 public:
  ActorExceptions();
  // `body` as an actor's code: an exception it throws (derived from std::exception; SimGrid's
  // own ForcefulKillException, which kills an actor, is not one and passes) is kept and ends
  // the simulation. Call it as Actor::create's argument: it hands back one of the stacks
  // check_stacks reserved, for SimGrid to allocate right after.
  std::function<void()> guard(std::function<void()> body);
  // Throws HostMemoryError (exit 6, one line with the figures) when the host cannot hold the
  // stacks of `actors` more actors: SimGrid ends the process (xbt_die, exit 134) when it
  // cannot allocate an actor's stack. The stacks are reserved (allocated, never touched) until
  // guard() hands them back one by one, so that what is allocated between this call and the
  // actors' creation cannot take their room.
  static void check_stacks(std::size_t actors);
  // Rethrows the first kept exception, if there is one; call after Engine::run returned.
  void rethrow_first() const;

 private:
  std::exception_ptr first_;
  // Host memory set aside for the way out: when an allocation fails, the heap is exhausted,
  // and killing the actors and unwinding the stacks allocate a little; freed first.
  std::unique_ptr<char[]> reserve_;
};

}  // namespace ncube

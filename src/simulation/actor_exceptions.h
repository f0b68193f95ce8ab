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
  // the simulation. Create the actor with create_actor (simulation/actor_stacks.h), which
  // hands it one of the stacks reserve_actor_stacks reserved.
  std::function<void()> guard(std::function<void()> body);
  // Rethrows the first kept exception, if there is one; call after Engine::run returned.
  void rethrow_first() const;

 private:
  std::exception_ptr first_;
  // Host memory set aside for the way out: when an allocation fails, the heap is exhausted,
  // and killing the actors and unwinding the stacks allocate a little; freed first.
  std::unique_ptr<char[]> reserve_;
};

}  // namespace ncube

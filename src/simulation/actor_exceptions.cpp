#include "simulation/actor_exceptions.h"

#include <unistd.h>

#include <cstdlib>
#include <memory>
#include <new>
#include <vector>

#include <simgrid/s4u/Actor.hpp>
#include <xbt/config.hpp>

namespace ncube {

namespace {
constexpr std::size_t kReserveBytes = std::size_t(16) << 20;  // not touched: no resident page
}

ActorExceptions::ActorExceptions() : reserve_(new char[kReserveBytes]) {}

std::function<void()> ActorExceptions::guard(std::function<void()> body) {
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
  // through malloc's posix_memalign, which reuses what is freed here.
  const std::size_t stack = std::size_t(simgrid::config::get_value<int>("contexts/stack-size")) * 1024 +
                            std::size_t(simgrid::config::get_value<int>("contexts/guard-size") + 1) *
                                std::size_t(sysconf(_SC_PAGESIZE));
  // One block per stack, as SimGrid allocates them (one block of all would be refused by the
  // kernel's overcommit heuristic on a large platform where the stacks one by one are not).
  std::vector<std::unique_ptr<void, decltype(&std::free)>> probes;
  probes.reserve(actors);
  for (std::size_t k = 0; k < actors; ++k) {
    probes.emplace_back(std::malloc(stack), &std::free);
    if (!probes.back()) throw std::bad_alloc();
  }
}

void ActorExceptions::rethrow_first() const {
  if (first_) std::rethrow_exception(first_);
}

}  // namespace ncube

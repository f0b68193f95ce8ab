#include "simulation/actor_exceptions.h"

#include <memory>
#include <utility>

#include <simgrid/s4u/Actor.hpp>

namespace ncube {

namespace {
constexpr std::size_t kReserveBytes = std::size_t(16) << 20;  // not touched: no resident page
}  // namespace

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

void ActorExceptions::rethrow_first() const {
  if (first_) std::rethrow_exception(first_);
}

}  // namespace ncube

#include "nodes/increment_exchange.h"

#include <stdexcept>

namespace ncube {

namespace {

// The largest power of two not above `nodes`, and its exponent.
int lower_power_of_two(int nodes, int& exponent) {
  exponent = 0;
  while ((2L << exponent) <= long(nodes)) ++exponent;
  return 1 << exponent;
}

}  // namespace

int IncrementExchange::messages_sent(int rank, int nodes) {
  int dimensions = 0;
  const int p = lower_power_of_two(nodes, dimensions);
  if (rank >= p) return 1;                         // its vector in; the sum comes back
  return dimensions + (rank < nodes - p ? 1 : 0);  // the steps, and the sum handed back
}

void IncrementExchange::sum(std::vector<Rgb>& increments, int iteration) {
  const int R = placement_.radiosity_processors;
  int dimensions = 0;
  const int p = lower_power_of_two(R, dimensions);
  const int fold = 0, unfold = dimensions + 1;  // the steps: fold, dimensions 1..L, unfold
  if (rank_ >= p) {  // above the power of two: give the vector, get the sum back
    send(rank_ - p, increments, iteration, fold);
    increments = std::move(receive(iteration, unfold)->increments);
    return;
  }
  const bool paired = rank_ < R - p;
  if (paired) add(increments, *receive(iteration, fold));
  for (int d = 0; d < dimensions; ++d) {
    send(rank_ ^ (1 << d), increments, iteration, d + 1);
    add(increments, *receive(iteration, d + 1));
  }
  if (paired) send(rank_ + p, increments, iteration, unfold);
}

void IncrementExchange::send(int to_rank, const std::vector<Rgb>& increments, int iteration,
                             int step) {
  auto message = std::make_unique<Message>();
  message->kind = MessageKind::kIncrements;
  message->increments = increments;
  message->iteration = iteration;
  message->block = step;
  runtime_.send(placement_.radiosity_node(to_rank), std::move(message));
}

std::unique_ptr<Message> IncrementExchange::receive(int iteration, int step) {
  for (auto it = early_.begin(); it != early_.end(); ++it) {
    if ((*it)->iteration == iteration && (*it)->block == step) {
      std::unique_ptr<Message> message = std::move(*it);
      early_.erase(it);
      return message;
    }
  }
  for (;;) {
    std::unique_ptr<Message> message = runtime_.receive({MessageKind::kIncrements});
    if (message->iteration == iteration && message->block == step) return message;
    early_.push_back(std::move(message));
  }
}

void IncrementExchange::add(std::vector<Rgb>& increments, const Message& received) {
  if (received.increments.size() != increments.size())
    throw std::logic_error("IncrementExchange: vectors of different lengths");
  WorkCounts work;
  for (std::size_t e = 0; e < increments.size(); ++e) increments[e] += received.increments[e];
  work.increments_combined = increments.size();
  runtime_.charge(work);
}

}  // namespace ncube

#include "nodes/ring_circulation.h"

#include <stdexcept>

namespace ncube {

namespace {

bool power_of_two(int n) { return n > 0 && (n & (n - 1)) == 0; }

}  // namespace

int RingCirculation::rank_at(int position, int ranks) {
  return power_of_two(ranks) ? position ^ (position >> 1) : position;
}

int RingCirculation::position_of(int rank, int ranks) {
  if (!power_of_two(ranks)) return rank;
  int position = 0;  // the inverse Gray code
  for (int g = rank; g; g >>= 1) position ^= g;
  return position;
}

RingCirculation::RingCirculation(NodeRuntime& runtime, const Placement& placement, int rank,
                                 std::vector<std::vector<std::size_t>> blocks)
    : runtime_(runtime),
      placement_(placement),
      rank_(rank),
      ranks_(placement.radiosity_processors),
      next_rank_(rank_at((position_of(rank, ranks_) + 1) % ranks_, ranks_)),
      blocks_(std::move(blocks)) {}

std::vector<ShooterChoice> RingCirculation::gather(const ShooterChoice& mine, int iteration) {
  std::vector<ShooterChoice> all{mine};
  ShooterChoice in_hand = mine;
  for (int step = 0; step + 1 < ranks_; ++step) {  // pass on what came last, take the next
    auto message = std::make_unique<Message>();
    message->candidate = in_hand;
    send(MessageKind::kCandidate, std::move(message), iteration, step);
    in_hand = receive(MessageKind::kCandidate, iteration, step)->candidate;
    all.push_back(in_hand);
  }
  WorkCounts compare;  // each node compares the candidates itself
  compare.shooter_candidates = std::uint64_t(ranks_);
  runtime_.charge(compare);
  return all;
}

std::vector<Rgb> RingCirculation::reduce_scatter(const std::vector<Rgb>& increments, int iteration) {
  const int position = position_of(rank_, ranks_);
  auto owner = [&](int offset) { return rank_at(((position + offset) % ranks_ + ranks_) % ranks_, ranks_); };
  // Step s sends the block of the owner s + 1 positions back and receives the one s + 2 back
  // (which this node adds to); the last received, R positions back, is this node's own.
  std::vector<Rgb> in_hand;
  for (std::size_t e : blocks_[std::size_t(owner(-1))]) in_hand.push_back(increments[e]);
  for (int step = 0; step + 1 < ranks_; ++step) {
    auto message = std::make_unique<Message>();
    message->increments = std::move(in_hand);
    send(MessageKind::kIncrements, std::move(message), iteration, step);
    in_hand = std::move(receive(MessageKind::kIncrements, iteration, step)->increments);
    const std::vector<std::size_t>& block = blocks_[std::size_t(owner(-2 - step))];
    if (in_hand.size() != block.size())
      throw std::logic_error("RingCirculation: a block of another length");
    for (std::size_t k = 0; k < block.size(); ++k) in_hand[k] += increments[block[k]];
    WorkCounts work;
    work.increments_combined = block.size();
    runtime_.charge(work);
  }
  return in_hand;
}

void RingCirculation::send(MessageKind kind, std::unique_ptr<Message> message, int iteration,
                           int step) {
  message->kind = kind;
  message->iteration = iteration;
  message->block = step;
  runtime_.send(placement_.radiosity_node(next_rank_), std::move(message));
}

std::unique_ptr<Message> RingCirculation::receive(MessageKind kind, int iteration, int step) {
  auto wanted = [&](const Message& m) {
    return m.kind == kind && m.iteration == iteration && m.block == step;
  };
  for (auto it = early_.begin(); it != early_.end(); ++it)
    if (wanted(**it)) {
      std::unique_ptr<Message> message = std::move(*it);
      early_.erase(it);
      return message;
    }
  for (;;) {
    std::unique_ptr<Message> message = runtime_.receive({kind});
    if (wanted(*message)) return message;
    early_.push_back(std::move(message));
  }
}

}  // namespace ncube

#include "nodes/collectives.h"

#include <algorithm>

namespace ncube {

int ShooterSelection::levels() const {
  int levels = 0;
  while ((1 << levels) < placement_.radiosity_processors) ++levels;
  return levels;
}

ShooterChoice ShooterSelection::reduce_to_master(const ShooterChoice& local_best,
                                                 std::vector<ProcessorLoad>& loads) {
  ShooterChoice best = local_best;
  const int R = placement_.radiosity_processors;
  for (int d = 0; d < levels(); ++d) {
    const int bit = 1 << d;
    if (rank_ & bit) {  // pass the subtree's best (and loads) to the parent, then done
      auto message = std::make_unique<Message>();
      message->kind = MessageKind::kCandidate;
      message->candidate = best;
      message->loads = loads;
      runtime_.send(placement_.radiosity_node(rank_ - bit), std::move(message));
      return best;
    }
    if (rank_ + bit < R) {  // a child's subtree best arrives
      const std::unique_ptr<Message> message = runtime_.receive({MessageKind::kCandidate});
      WorkCounts compare;
      compare.shooter_candidates = 1;
      runtime_.charge(compare);
      if (message->candidate.better_than(best)) best = message->candidate;
      loads.insert(loads.end(), message->loads.begin(), message->loads.end());
    }
  }
  std::sort(loads.begin(), loads.end(),
            [](const ProcessorLoad& a, const ProcessorLoad& b) { return a.rank < b.rank; });
  return best;
}

Decision ShooterSelection::broadcast_from_master(const Decision& decision) {
  Decision result = decision;
  int top = levels();  // the master sends on every level
  if (rank_ != 0) {
    const std::unique_ptr<Message> message = runtime_.receive({MessageKind::kShooter, MessageKind::kStop});
    result = {message->candidate, message->transfers, message->out_of_memory};
    top = __builtin_ctz(unsigned(rank_));  // levels below this rank's lowest set bit
  }
  for (int d = top - 1; d >= 0; --d) {
    const int child = rank_ + (1 << d);
    if (child >= placement_.radiosity_processors) continue;
    auto message = std::make_unique<Message>();
    message->kind = result.shooter.patch < 0 ? MessageKind::kStop : MessageKind::kShooter;
    message->candidate = result.shooter;
    message->transfers = result.transfers;
    message->out_of_memory = result.out_of_memory;
    runtime_.send(placement_.radiosity_node(child), std::move(message));
  }
  return result;
}

}  // namespace ncube

// The two circulations of Çapın, Aykanat & Özgüç's scheme (--parallelisation circulation;
// docs/model.md, "The circulation opponent"): the nodes form a ring embedded in the hypercube
// (their iPSC/2 runs were "ring-embedded"; a Gray-code order makes every ring step one hop
// when R is a power of two), and data travel round it one neighbour step at a time.
//   - gather: every node's best candidate goes round the ring (R - 1 steps, one shooter
//     record a message), so every node ends with all R candidates and decides as the others;
//   - reduce_scatter: the light distribution. Each node holds increments for every element
//     of the scene (its shooter's light); the block of owner j (j's elements) starts at j's
//     ring successor and goes once round the ring, each node adding its own increments to it,
//     so that after R - 1 steps every node holds the sum of every node's increments for its
//     own elements only: R - 1 messages a node, (R - 1) x (12 E + 8 R) bytes over the machine
//     an iteration, where an allreduce of whole vectors (the `shooters` variant) sends
//     R log2 R (12 E + 8).
#pragma once

#include <memory>
#include <vector>

#include "nodes/node_runtime.h"
#include "nodes/placement.h"

namespace ncube {

class RingCirculation {
 public:
  // `blocks[j]`: the scene element indices of rank j's elements, in the order j holds them.
  RingCirculation(NodeRuntime& runtime, const Placement& placement, int rank,
                  std::vector<std::vector<std::size_t>> blocks);

  // Every rank's candidate of iteration `iteration` (this rank's is `mine`), in the order they
  // arrived here (this rank's first; the choice does not depend on the order).
  std::vector<ShooterChoice> gather(const ShooterChoice& mine, int iteration);

  // This rank's block of the sum over all ranks of `increments` (one RGB per scene element),
  // in the order of blocks[rank]; charges each received element's adds (increments_combined).
  std::vector<Rgb> reduce_scatter(const std::vector<Rgb>& increments, int iteration);

  // The rank at ring position `position` (0..R-1), and this rank's ring position: a Gray code
  // when R is a power of two (ring neighbours are hypercube neighbours), else rank order.
  static int rank_at(int position, int ranks);
  static int position_of(int rank, int ranks);

 private:
  void send(MessageKind kind, std::unique_ptr<Message> message, int iteration, int step);
  std::unique_ptr<Message> receive(MessageKind kind, int iteration, int step);

  NodeRuntime& runtime_;
  const Placement& placement_;
  int rank_;
  int ranks_;
  int next_rank_;
  std::vector<std::vector<std::size_t>> blocks_;
  std::vector<std::unique_ptr<Message>> early_;  // messages of a later step that came first
};

}  // namespace ncube

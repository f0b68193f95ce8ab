// The exchange of the shooter-centred scheme (--parallelisation shooters; docs/model.md,
// "The shooter-centred scheme"): after each node has shot its shooter into its own vector of
// radiosity increments (one RGB per scene element), every node needs the sum of all the
// nodes' vectors, the "distribution of radiosity values after form factor calculation" the
// paper's section 6 says its own method avoids. An allreduce by recursive doubling along the
// hypercube's dimensions: in step d each node swaps its sum so far with the node across
// dimension d and adds what it receives, so after log2(R) steps every node holds the whole
// sum; every message is one hypercube hop. With R not a power of two, the R - p nodes above
// the largest power of two p first give their vectors to node rank - p (one hop: the same
// bit) and get the sum back at the end. Every vector travels whole: elements in the scene's
// order, radiosity_increment_bytes each.
#pragma once

#include <memory>
#include <vector>

#include "nodes/node_runtime.h"
#include "nodes/placement.h"

namespace ncube {

class IncrementExchange {
 public:
  IncrementExchange(NodeRuntime& runtime, const Placement& placement, int rank)
      : runtime_(runtime), placement_(placement), rank_(rank) {}

  // Replaces `increments` (this node's vector) by the sum of every node's vector of
  // iteration `iteration`; charges each received element's adds (increments_combined).
  // The sum is the same on every node to the last bit: each step adds two partial sums,
  // and IEEE addition is commutative.
  void sum(std::vector<Rgb>& increments, int iteration);

  // The messages this node sends in one exchange among `nodes` ranks (for the docs' and the
  // tests' hand-worked byte counts): log2(p) dimension steps, plus one to fold in or hand
  // back the sum for the nodes paired above the largest power of two p.
  static int messages_sent(int rank, int nodes);

 private:
  void send(int to_rank, const std::vector<Rgb>& increments, int iteration, int step);
  // The message of `iteration` and `step` (messages of later steps that arrive first are
  // kept until their turn).
  std::unique_ptr<Message> receive(int iteration, int step);
  void add(std::vector<Rgb>& increments, const Message& received);

  NodeRuntime& runtime_;
  const Placement& placement_;
  int rank_;
  std::vector<std::unique_ptr<Message>> early_;
};

}  // namespace ncube

// Choosing the shooter among the radiosity processors (paper section 2.2: every processor
// sends its best patch to the master, which sends the chosen shooter to all). Both travel
// along a binomial tree over the radiosity processors' ranks: the candidates are combined
// on the way up (each node keeps the better of its own and its children's), the decision is
// copied on the way down. With the placement rule the tree's edges are hypercube links when
// V + 1 is a power of two, so each of the log2(R) steps costs one hop. When loads can change
// (sections 4.1, 4.2) the candidates carry the processors' loads up, and the decision carries
// the master's balancing orders down.
#pragma once

#include "nodes/node_runtime.h"
#include "nodes/placement.h"

namespace ncube {

// What the master sends down: the shooter (patch -1: stop) and balancing orders.
struct Decision {
  ShooterChoice shooter;
  std::vector<Transfer> transfers;
  bool out_of_memory = false;  // stop because a processor cannot make its cuts
};

class ShooterSelection {
 public:
  ShooterSelection(NodeRuntime& runtime, const Placement& placement, int rank)
      : runtime_(runtime), placement_(placement), rank_(rank) {}

  bool is_master() const { return rank_ == 0; }
  // Combines the candidates of this rank's subtree and passes the best towards the master;
  // at the master, returns the global best (elsewhere: the subtree's best). `loads` holds
  // this rank's load (or nothing); at the master it ends with every rank's, in rank order.
  ShooterChoice reduce_to_master(const ShooterChoice& local_best, std::vector<ProcessorLoad>& loads);
  // The master's decision reaches every radiosity processor; returns it.
  Decision broadcast_from_master(const Decision& decision);

 private:
  int levels() const;  // ceil(log2(R))

  NodeRuntime& runtime_;
  const Placement& placement_;
  int rank_;
};

}  // namespace ncube

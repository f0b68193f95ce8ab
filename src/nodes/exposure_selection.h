// The picture's exposure agreed by all nodes of the rendering phase (paper section 2.3):
// the tone mapping needs the 95th percentile of the luminance of every visible sample of
// the picture, which lies spread over the nodes' rows. A radix select finds that sample's
// exact value: in each of kSelectionRounds rounds every node counts its samples still
// matching the key prefix chosen so far by their next 8-bit digit, the histograms are
// added up a binomial tree to node 0, node 0 chooses the digit, and the choice goes back
// down the tree. Every node then computes the same exposure as the sequential render.
#pragma once

#include "nodes/node_runtime.h"
#include "render/frame_share.h"

namespace ncube {

class ExposureSelection {
 public:
  ExposureSelection(NodeRuntime& runtime, int node, int nodes)
      : runtime_(runtime), node_(node), nodes_(nodes) {}

  // The exposure scale of the whole picture, given this node's share of it.
  double agree(const FrameShare& frame);

 private:
  void count_round(const FrameShare& frame, int round, ExposureRound& state);
  void reduce_to_node0(int round, ExposureRound& state);
  void broadcast_from_node0(int round, ExposureRound& state);
  int levels() const;  // ceil(log2(N))

  NodeRuntime& runtime_;
  int node_, nodes_;
};

// Node 0's choice of round `round`'s digits from the summed histograms (state.histogram):
// updates count (round 0), rank and prefix of each set.
void choose_digits(int round, ExposureRound& state);

}  // namespace ncube

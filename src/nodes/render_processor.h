// A node of the rendering phase (paper section 2.3), on every node of the run after the
// radiosity has converged: "We partition the picture into N parts and assign each part to
// one of the N processors, we can use a ring topology to distribute all patches to all
// processors, or exploit the network topology more fully." Each node rasterises every
// element into its part's rows as the elements reach it, the nodes agree on the exposure,
// and node 0 collects the finished rows.
#pragma once

#include <map>
#include <optional>

#include "nodes/exposure_selection.h"
#include "nodes/node_runtime.h"
#include "nodes/render_setup.h"
#include "render/frame_share.h"

namespace ncube {

class RenderProcessor {
 public:
  RenderProcessor(const RenderSetup& setup, int node, NodeRuntime& runtime);

  void run();  // the actor's body

  // Counted seconds spent rasterising (the load the partition spreads).
  double rasterise_seconds() const { return rasterise_seconds_; }
  int rows() const { return setup_.rows_of(node_).count(); }
  // At node 0 after the run: the assembled picture.
  const Image& picture() const { return picture_; }

 private:
  void rasterise(const ElementShare& share);
  void distribute_over_ring();
  void distribute_over_hypercube();
  void collect_pieces(const Image& own_rows);

  const RenderSetup& setup_;
  int node_;
  NodeRuntime& runtime_;
  std::optional<FrameShare> frame_;
  double rasterise_seconds_ = 0.0;
  Image picture_;
};

}  // namespace ncube

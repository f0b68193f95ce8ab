#include "nodes/render_processor.h"

#include <xbt/log.h>

// --log=ncube_render.thresh:debug shows each node's steps of the rendering phase.
XBT_LOG_NEW_DEFAULT_CATEGORY(ncube_render, "the rendering phase (section 2.3)");

namespace ncube {

RenderProcessor::RenderProcessor(const RenderSetup& setup, int node, NodeRuntime& runtime)
    : setup_(setup), node_(node), runtime_(runtime) {}

void RenderProcessor::run() {
  runtime_.start();
  frame_.emplace(setup_.scene, setup_.scene.camera, setup_.options.width, setup_.options.height,
                 setup_.rows_of(node_), setup_.options.outline_elements);
  // Every element reaches every node, which draws it into the rows of its part.
  if (setup_.options.distribution == RenderDistribution::kRing)
    distribute_over_ring();
  else
    distribute_over_hypercube();
  // The tone mapping needs the whole picture's luminances: all nodes agree on the exposure.
  const double scale = ExposureSelection(runtime_, node_, setup_.nodes).agree(*frame_);
  RenderCounts work;
  const Image rows = frame_->resolve(scale, work);
  runtime_.charge(work);
  frame_.reset();  // the frame share is freed before node 0 collects the picture
  collect_pieces(rows);
  runtime_.finish();
}

void RenderProcessor::rasterise(const ElementShare& share) {
  RenderCounts work;
  for (const RenderElement& element : *share) frame_->draw(element, work);
  const double before = runtime_.stats().compute_seconds;
  runtime_.charge(work);
  rasterise_seconds_ += runtime_.stats().compute_seconds - before;
}

void RenderProcessor::distribute_over_ring() {
  // N - 1 steps: in step s each node passes on to its successor what it received in step
  // s - 1 (its own elements in step 1) and receives the share of the node s places before
  // it. Flow control keeps a node's memory at two shares: it sends the next share only
  // when the successor has taken the last one (a credit message).
  const int N = setup_.nodes;
  const int p = ring_position(node_, N);
  const int next = ring_node((p + 1) % N, N), previous = ring_node((p + N - 1) % N, N);
  ElementShare current = setup_.shares[std::size_t(node_)];
  rasterise(current);
  for (int step = 1; step < N; ++step) {
    if (step > 1) runtime_.receive({MessageKind::kCredit});
    auto message = std::make_unique<Message>();
    message->kind = MessageKind::kElements;
    message->block = step;
    message->shares = {current};
    runtime_.send(next, std::move(message));
    const std::unique_ptr<Message> arrived = runtime_.receive({MessageKind::kElements});
    if (step + 1 < N) {  // the predecessor has one more share to pass on
      auto credit = std::make_unique<Message>();
      credit->kind = MessageKind::kCredit;
      runtime_.send(previous, std::move(credit));
    }
    current = arrived->shares.front();
    rasterise(current);
  }
}

void RenderProcessor::distribute_over_hypercube() {
  // Recursive doubling: in step d every node sends all it holds to its neighbour across
  // dimension d and receives as much, so after log2 N steps every node holds everything.
  std::vector<ElementShare> held = {setup_.shares[std::size_t(node_)]};
  rasterise(held.front());
  std::map<int, std::unique_ptr<Message>> early;  // a later step's message that came first
  for (int d = 0; (1 << d) < setup_.nodes; ++d) {
    auto message = std::make_unique<Message>();
    message->kind = MessageKind::kElements;
    message->block = d;
    message->shares = held;
    runtime_.send(node_ ^ (1 << d), std::move(message));
    std::unique_ptr<Message> arrived;
    if (early.count(d)) {
      arrived = std::move(early[d]);
      early.erase(d);
    }
    while (!arrived) {
      std::unique_ptr<Message> m = runtime_.receive({MessageKind::kElements});
      if (m->block == d)
        arrived = std::move(m);
      else
        early[m->block] = std::move(m);
    }
    for (const ElementShare& share : arrived->shares) {
      rasterise(share);
      held.push_back(share);
    }
  }
}

void RenderProcessor::collect_pieces(const Image& own_rows) {
  // A gather: every node sends its finished rows to node 0, which places them.
  if (node_ != 0) {
    auto message = std::make_unique<Message>();
    message->kind = MessageKind::kPixels;
    message->pixels = own_rows;
    runtime_.send(0, std::move(message));
    return;
  }
  picture_ = Image(setup_.options.width, setup_.options.height);
  const auto place = [this](int node, const Image& rows) {
    const RowShare share = setup_.rows_of(node);
    for (int local = 0; local < rows.height; ++local)
      for (int x = 0; x < rows.width; ++x) picture_.at(x, share.row_at(local)) = rows.at(x, local);
  };
  place(0, own_rows);
  for (int k = 1; k < setup_.nodes; ++k) {
    const std::unique_ptr<Message> piece = runtime_.receive({MessageKind::kPixels});
    place(piece->from, piece->pixels);
  }
}

}  // namespace ncube

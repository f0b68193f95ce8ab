#include "nodes/exposure_selection.h"

#include <algorithm>

#include "render/exposure.h"

namespace ncube {

int ExposureSelection::levels() const {
  int levels = 0;
  while ((1 << levels) < nodes_) ++levels;
  return levels;
}

void choose_digits(int round, ExposureRound& state) {
  for (int set = 0; set < 2; ++set) {
    const std::uint64_t* h = &state.histogram[std::size_t(set) * kSelectionBuckets];
    if (round == 0) {
      state.count[set] = 0;
      for (int b = 0; b < kSelectionBuckets; ++b) state.count[set] += h[b];
      state.rank[set] = percentile_rank(state.count[set]);
    }
    if (state.count[set] == 0) continue;
    std::uint64_t below = 0;
    int digit = 0;
    while (below + h[digit] <= state.rank[set]) below += h[digit++];
    state.rank[set] -= below;
    state.prefix[set] |= std::uint64_t(digit) << (56 - 8 * round);
  }
}

void ExposureSelection::count_round(const FrameShare& frame, int round, ExposureRound& state) {
  state.histogram.assign(2 * kSelectionBuckets, 0);
  RenderCounts work;
  frame.for_each_visible([&](const Rgb& radiosity, bool emitter) {
    ++work.exposure_samples;
    const double l = luminance(radiosity);
    const std::uint64_t key = order_key(l);
    for (int set = emitter ? 1 : 0; set < 2; ++set) {
      if (round == 0) state.max[set] = std::max(state.max[set], l);
      if (key_matches(key, state.prefix[set], round))
        ++state.histogram[std::size_t(set) * kSelectionBuckets + key_digit(key, round)];
    }
  });
  runtime_.charge(work);
}

void ExposureSelection::reduce_to_node0(int round, ExposureRound& state) {
  for (int d = 0; d < levels(); ++d) {
    const int bit = 1 << d;
    if (node_ & bit) {  // pass the subtree's histograms to the parent, then done
      auto message = std::make_unique<Message>();
      message->kind = MessageKind::kHistogram;
      message->block = round;
      message->exposure = state;
      runtime_.send(node_ - bit, std::move(message));
      return;
    }
    if (node_ + bit < nodes_) {  // a child subtree's histograms arrive
      const std::unique_ptr<Message> child = runtime_.receive({MessageKind::kHistogram});
      for (std::size_t b = 0; b < state.histogram.size(); ++b)
        state.histogram[b] += child->exposure.histogram[b];
      for (int set = 0; set < 2; ++set)
        state.max[set] = std::max(state.max[set], child->exposure.max[set]);
      RenderCounts work;
      work.histogram_buckets = state.histogram.size();
      runtime_.charge(work);
    }
  }
}

void ExposureSelection::broadcast_from_node0(int round, ExposureRound& state) {
  int top = levels();
  if (node_ != 0) {
    const std::unique_ptr<Message> choice = runtime_.receive({MessageKind::kSelection});
    state = choice->exposure;
    top = __builtin_ctz(unsigned(node_));
  }
  for (int d = top - 1; d >= 0; --d) {
    const int child = node_ + (1 << d);
    if (child >= nodes_) continue;
    auto message = std::make_unique<Message>();
    message->kind = MessageKind::kSelection;
    message->block = round;
    message->exposure = state;
    message->exposure.histogram.clear();
    runtime_.send(child, std::move(message));
  }
}

double ExposureSelection::agree(const FrameShare& frame) {
  ExposureRound state;
  for (int round = 0; round < kSelectionRounds; ++round) {
    count_round(frame, round, state);
    reduce_to_node0(round, state);
    if (node_ == 0) choose_digits(round, state);
    broadcast_from_node0(round, state);
  }
  LuminanceSelection selection[2];
  for (int set = 0; set < 2; ++set)
    selection[set] = {state.count[set], from_order_key(state.prefix[set]), state.max[set]};
  return exposure_scale(selection[0], selection[1]);
}

}  // namespace ncube

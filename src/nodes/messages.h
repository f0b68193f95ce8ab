// The messages the node programs exchange, with their modeled sizes (cost_model.json).
// The host carries real data in them; the network is charged the modeled bytes.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "nodes/load_balancing.h"
#include "radiosity/radiosity_engine.h"
#include "render/frame_share.h"

namespace ncube {

enum class MessageKind {
  kCandidate,  // a radiosity processor's best shooter candidate, on its way to the master
  kShooter,    // the chosen shooter (geometry and unshot radiosity), on its way to all
  kStop,       // converged or iteration limit reached: every node ends
  kPoints,     // a block of visibility points, radiosity -> visibility processor
  kAnswers,    // one part mask per point of a block, visibility -> radiosity processor
  kPatches,    // patches with their elements, from one radiosity processor to another (4.2)
  // The rendering phase (section 2.3):
  kElements,   // render records of one or more nodes' shares, passed on (ring, hypercube)
  kCredit,     // ring: "your last message was taken", so the next may come
  kHistogram,  // a subtree's luminance histograms, towards node 0 (exposure)
  kSelection,  // node 0's choice of a round's digits, towards every node (exposure)
  kPixels,     // a node's finished rows, to node 0
};

// The state of the exposure's radix select (render/exposure.h), per set: [0] the
// non-emitting visible samples, [1] all visible samples.
struct ExposureRound {
  std::uint64_t count[2] = {0, 0};   // samples in the set (known after round 0)
  std::uint64_t rank[2] = {0, 0};    // rank of the wanted value among the samples still matching
  std::uint64_t prefix[2] = {0, 0};  // the key digits chosen so far
  double max[2] = {0.0, 0.0};        // largest luminance in the set
  std::vector<std::uint64_t> histogram;  // kHistogram: 2 x kSelectionBuckets counts
};

using ElementShare = std::shared_ptr<const std::vector<RenderElement>>;

struct Message {
  MessageKind kind = MessageKind::kStop;
  int from = -1;             // sending node
  ShooterChoice candidate;   // kCandidate, kShooter
  std::vector<ProcessorLoad> loads;  // kCandidate: the subtree's loads (subdivision or balancing on)
  std::vector<Transfer> transfers;   // kShooter: the master's balancing orders (4.2)
  bool out_of_memory = false;        // kStop: a processor cannot make its cuts (4.1, 4.2)
  std::vector<StoredPatch> patches;  // kPatches
  int block = -1;            // kPoints, kAnswers
  std::vector<Vec3> points;  // kPoints
  std::vector<int> point_patches;  // kPoints: the patch of each point
  std::vector<PartMask> masks;     // kAnswers
  std::vector<ElementShare> shares;  // kElements: the shares carried (block: the step)
  ExposureRound exposure;            // kHistogram, kSelection (block: the round)
  Image pixels;                      // kPixels: the sender's rows, in order
};

}  // namespace ncube

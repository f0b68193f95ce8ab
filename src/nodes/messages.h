// The messages the node programs exchange, with their modeled sizes (cost_model.json).
// The host carries real data in them; the network is charged the modeled bytes, which
// payload_bytes computes from each message's content (NodeRuntime::send adds the header).
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "machine/cost_model.h"
#include "nodes/load_balancing.h"
#include "radiosity/radiosity_engine.h"
#include "render/frame_share.h"

namespace ncube {

// Each kind with its modeled payload (payload_bytes; the sizes are cost_model.json's).
enum class MessageKind {
  kCandidate,  // a radiosity processor's best shooter candidate, on its way to the master:
               // one shooter record, and a load record per load carried (4.1, 4.2)
  kShooter,    // the chosen shooter (geometry and unshot radiosity), on its way to all:
               // one shooter record, and a transfer order per balancing order (4.2)
  kStop,       // converged, iteration limit reached or out of memory: every node ends. Sent
               // where the shooter would be, as a shooter record with no patch
  kPoints,     // a block of visibility points, radiosity -> visibility processor: a point
               // record per point
  kAnswers,    // one part mask per point of a block, visibility -> radiosity processor:
               // ceil(M / 8) bytes per mask (part_mask_bytes)
  kPatches,    // patches with their elements, from one radiosity processor to another (4.2):
               // each patch's bytes as held (patch_record_bytes)
  kIncrements,  // the shooter-centred scheme (--parallelisation shooters): one step of the
                // exchange of the iteration's radiosity increments, a node's sum so far for
                // every element of the scene: radiosity_increment_bytes per element
  // The rendering phase (section 2.3):
  kElements,   // render records of one or more nodes' shares, passed on (ring, hypercube):
               // a render element record per element carried, a render vertex per T-vertex
               // on its boundary (render_record_bytes)
  kCredit,     // ring: "your last message was taken", so the next may come: the header only
  kHistogram,  // a subtree's luminance histograms, towards node 0 (exposure): one round's
               // histograms
  kSelection,  // node 0's choice of a round's digits, towards every node (exposure): one
               // round's selection
  kPixels,     // a node's finished rows, to node 0: a pixel record per pixel
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
  std::vector<long> patch_records;   // kPatches: each patch's element records (patch_records)
  bool patch_geometry = false;       // kPatches: the patches' geometry travels with them (V > 0)
  int block = -1;            // kPoints, kAnswers
  std::vector<Vec3> points;  // kPoints
  std::vector<int> point_patches;  // kPoints: the patch of each point
  std::vector<PartMask> masks;     // kAnswers
  int mask_parts = 0;              // kAnswers: parts per mask (the shooter's M)
  std::vector<Rgb> increments;       // kIncrements: per scene element, in scene order
  int iteration = -1;                // kIncrements: the iteration (block: the step)
  std::vector<ElementShare> shares;  // kElements: the shares carried (block: the step)
  ExposureRound exposure;            // kHistogram, kSelection (block: the round)
  Image pixels;                      // kPixels: the sender's rows, in order
};

// Bytes of one part mask of M parts (one bit per part).
double part_mask_bytes(int parts);

// The modeled bytes of `message`'s content, without the header (see MessageKind).
double payload_bytes(const Message& message, const CostModel& costs);

}  // namespace ncube

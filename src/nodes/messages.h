// The messages the node programs exchange, with their modeled sizes (cost_model.json).
// The host carries real data in them; the network is charged the modeled bytes.
#pragma once

#include <vector>

#include "radiosity/radiosity_engine.h"

namespace ncube {

enum class MessageKind {
  kCandidate,  // a radiosity processor's best shooter candidate, on its way to the master
  kShooter,    // the chosen shooter (geometry and unshot radiosity), on its way to all
  kStop,       // converged or iteration limit reached: every node ends
  kPoints,     // a block of visibility points, radiosity -> visibility processor
  kAnswers,    // one part mask per point of a block, visibility -> radiosity processor
};

struct Message {
  MessageKind kind = MessageKind::kStop;
  int from = -1;             // sending node
  ShooterChoice candidate;   // kCandidate, kShooter
  int block = -1;            // kPoints, kAnswers
  std::vector<Vec3> points;  // kPoints
  std::vector<int> point_patches;  // kPoints: the patch of each point
  std::vector<PartMask> masks;     // kAnswers
};

}  // namespace ncube

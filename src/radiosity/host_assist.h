// The points where the host may help the simulated program run faster on this computer. The
// simulated side calls them at fixed places (the engine's form factors, the blocks a
// radiosity processor sends, the end of a shot); the implementations live on the host side
// (src/host/: threads, and the threads computing ahead, lookahead.h).
//
// Contract: an implementation computes only what the program would compute itself, with the
// same functions on the same inputs, and changes no answer, no count, no message and no
// simulated second. The default helps with nothing: the program then computes everything
// itself on one thread (as with --reference-visibility).
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <vector>

#include "visibility/point_block.h"
#include "visibility/shooter.h"

namespace ncube {

class RadiosityEngine;

class HostAssist {
 public:
  virtual ~HostAssist() = default;

  // Runs body(begin, end) over disjoint chunks covering [0, count) of independent items,
  // perhaps on several host threads (chunks of at least `grain` items, in any order).
  virtual void share_out(std::size_t count, std::size_t /*grain*/,
                         const std::function<void(std::size_t, std::size_t)>& body) const {
    if (count > 0) body(0, count);
  }

  // The blocks one radiosity processor sends for one shot, as the host knows them.
  class PostedShot {
   public:
    virtual ~PostedShot() = default;
  };
  // A radiosity processor is about to send points[0 .. n) (with their patches) in blocks of
  // `block_size` to its visibility processors for `shooter` (section 3). Null: no help.
  virtual std::shared_ptr<PostedShot> blocks_to_send(const Shooter& /*shooter*/,
                                                     const std::vector<Vec3>& /*points*/,
                                                     const std::vector<int>& /*patches*/,
                                                     int /*block_size*/) {
    return nullptr;
  }
  // The receivers' form factors (receiver_form_factor) of block `block`, computed ahead,
  // when `visible` (count masks) is exactly the block's visibility; null otherwise.
  virtual const double* form_factors(PostedShot& /*shot*/, int /*block*/,
                                     const PartMask* /*visible*/, std::size_t /*count*/) {
    return nullptr;
  }
  // The receivers' form factors (receiver_form_factor) at the points of `receivers` for
  // `shooter` and the visibility `visible`, remembered from an earlier shot with exactly
  // the same question: writes them to `out` and returns true. remember_form_factors keeps
  // them. The default remembers nothing (remembers_form_factors: whether to ask at all).
  virtual bool remembers_form_factors() const { return false; }
  virtual bool remembered_form_factors(const Shooter& /*shooter*/, const PointBlock& /*receivers*/,
                                       const PartMask* /*visible*/, double* /*out*/) {
    return false;
  }
  virtual void remember_form_factors(const Shooter& /*shooter*/, const PointBlock& /*receivers*/,
                                     const PartMask* /*visible*/, const double* /*values*/) {}
  // Radiosity processor `rank`'s engine before its first shot, and any engine after a shot.
  virtual void engine_started(int /*rank*/, const RadiosityEngine& /*engine*/) {}
  virtual void shot_finished(const RadiosityEngine& /*engine*/) {}
};

}  // namespace ncube

// All patches of a scene in one Embree scene, shared by every occluder set of that scene in
// the process: a node's set uses it directly when it holds the whole scene (V = 0, section
// 2.2); a visibility processor's share (section 3) reads, for each ray, which patches of the
// whole scene block it and keeps those of its own share. The V visibility processors of a
// group are asked about the same block of points for the same shooter, so the lists of a
// block are computed once and handed to all V (host-side memo: every answer is still what
// the exact test says for that share's patches; no count depends on it). Shares testing all
// patches need only "does my share block this ray": they register as sets and get one bit
// per set and ray (cheaper than lists of every blocker, which first-blocker sets read).
// Contract (host side): it changes no answer and no count (tests/fast_occluders_scenes_test.cpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <memory>
#include <vector>

#include "host/answer_cache.h"
#include "host/embree_scene.h"
#include "host/host_side.h"
#include "host/question_key.h"
#include "scene/scene.h"

namespace ncube {

class SceneBlockers {
 public:
  // The process's blockers of `scene` (built on first use, shared while in use).
  static std::shared_ptr<const SceneBlockers> for_scene(const Scene& scene);

  explicit SceneBlockers(const Scene& scene);

  // The scale of the scene's coordinates (single-precision rounding is relative to it).
  double scale() const { return scale_; }
  // Rays with both ends within band() of a plane cross it at less than kBand radians: the
  // exact test alone decides them against that plane's patches (fast_occluders.h). Every
  // other crossing is steeper, and Embree's patches are grown by kPad of the scale: over a
  // sine above kBand that covers single-precision errors up to kPad * kBand = 1e-6 of the
  // scale (several units in the last place; docs/performance.md). A wider band means fewer
  // false hits on small patches and more rays for the exact in-plane tests: 5e-3 was the
  // fastest pair with that product for scene3 to convergence (docs/performance-log.md,
  // 2026-11-25).
  static constexpr double kBand = 5e-3, kPad = 2e-4;
  double band() const { return kBand * scale_; }
  // The Embree scene of all patches; positions are scene patch indices.
  const EmbreeScene& embree() const { return *embree_; }
  // The answers of this scene's occluder sets across iterations (answer_cache.h), under
  // one budget for all of them.
  AnswerCache& answer_cache() const { return answer_cache_; }

  // For point k (on scene patch receiver_patches[k]) and shooter part r: every scene patch,
  // other than the point's and the shooter's, that the segment crosses by the exact test:
  // patches[offsets[k * M + r] .. offsets[k * M + r + 1]).
  struct Lists {
    int part_count = 0;
    std::vector<int> offsets, patches;
  };
  // Computed on `threads` host threads; with `memo`, a block asked about before (same
  // points, same shooter) is answered from memory. Not to be called from two threads at once.
  std::shared_ptr<const Lists> blockers(const PointBlock& block, const Shooter& shooter,
                                        int threads, bool memo) const;

  // Cheaper when only "does my set block it" is asked (a share, testing all patches): sets
  // of patches registered here (up to 64 at a time; -1 when full) get one bit each, and
  // per point and ray the answer is the bits of the sets holding a blocker. Like the queries,
  // not to be called from two threads at once (occluder sets are built before a run).
  int register_set(const std::vector<int>& scene_patches) const;
  void unregister_set(int bit) const;
  struct SetMasks {
    int part_count = 0;
    // [k * 64 + s]: bit r set when set s blocks the ray from point k to part r (per set, so
    // that each of the V shares reads its answer in one word)
    std::vector<PartMask> blocked;
  };
  std::shared_ptr<const SetMasks> blocked_sets(const PointBlock& block, const Shooter& shooter,
                                               int threads) const;
  // The same without the memo, on the calling thread only: safe on several host threads at
  // once (for the threads computing ahead, lookahead.h). So is blockers(..., 1, false).
  std::shared_ptr<const SetMasks> blocked_sets_here(const PointBlock& block,
                                                    const Shooter& shooter) const {
    return compute_sets(block, shooter, 1);
  }

 private:
  struct Entry {
    int kind;               // 0: lists, 1: set masks
    std::uint64_t version;  // of the registered sets (masks only)
    ShooterKey shooter;
    BlockKey block;
    std::shared_ptr<const Lists> lists;
    std::shared_ptr<const SetMasks> masks;
  };
  // The memo entry for this block, or null.
  Entry* find(int kind, const PointBlock& block, const Shooter& shooter) const;
  void remember(Entry entry) const;
  std::shared_ptr<const Lists> compute(const PointBlock& block, const Shooter& shooter,
                                       int threads) const;
  std::shared_ptr<const SetMasks> compute_sets(const PointBlock& block, const Shooter& shooter,
                                               int threads) const;

  double scale_;
  std::vector<PatchCandidate> candidates_;  // scene order
  std::unique_ptr<EmbreeScene> embree_;
  mutable std::deque<Entry> memo_;          // most recent first
  mutable AnswerCache answer_cache_{AnswerCache::default_budget_bytes()};
  mutable std::vector<std::uint64_t> sets_of_patch_;  // per scene patch: registered sets
  mutable std::uint64_t registered_ = 0, version_ = 0;
};

}  // namespace ncube

// A host-side memory of visibility answers across iterations (docs/performance.md). The
// progressive run shoots the same patch many times (scene2 at R=8, V=7: 933 shots of 335
// patches), and each time a set of occluders is asked about the same blocks of points; its
// answers and counts are then the same as the last time, because they depend only on the
// set's patches, the shooter's patch and ray targets, and the points with their patches.
// This cache keeps them under a budget of host memory and hands them back only for exactly
// the same question: the points, their patches and the targets are compared bit for bit
// (a hash only finds the candidates), never assumed stable between iterations. The simulated
// machine never sees it: the counts it is charged for are the counts of the brute-force
// loop, whether computed now or remembered.
// Contract (host side): it changes no answer and no count; it hands back only answers to the
// very same question (question_key.h; tests/answer_cache_test.cpp).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <list>
#include <memory>
#include <mutex>
#include <unordered_map>
#include <vector>

#include "counts/work_counts.h"
#include "host/host_side.h"
#include "host/question_key.h"
#include "visibility/shooter.h"

namespace ncube {

class AnswerCache {
 public:
  // Choice: 384 MiB by default. scene3 at R=8, V=7 to convergence (830 shots of 314
  // patches) takes 95.8 s with it, 94.4 s with 448 MiB and 129 s with 256 MiB, at a peak of
  // 542 MiB for the whole run (docs/performance-log.md, 2026-11-25); NCUBE_ANSWER_CACHE_MB
  // overrides it (0 turns the cache off).
  static std::size_t default_budget_bytes();

  explicit AnswerCache(std::size_t budget_bytes);
  AnswerCache(const AnswerCache&) = delete;
  AnswerCache& operator=(const AnswerCache&) = delete;

  // When set `set` (an id no other set ever had) was asked about exactly this block for
  // this shooter before and its answers are still held: writes them to masks[0 .. count),
  // adds the block's counts to `counts` and returns true.
  bool find(std::uint64_t set, const Shooter& shooter, const PointBlock& block, PartMask* masks,
            WorkCounts& counts);
  // Remembers masks[0 .. count) and the block's counts. Over budget, the answers of the
  // shooter shot least often go first (the least recently shot among equals): progressive
  // refinement shoots its bright patches again and again. Answers larger than the whole
  // budget are not kept.
  void store(std::uint64_t set, const Shooter& shooter, const PointBlock& block,
             const PartMask* masks, const WorkCounts& counts);
  // Values per point computed from a block's answers (the form factors of lookahead.h), kept
  // under the same budget: found only for the same set id, shooter and block, and the same
  // `masks` (compared in full).
  bool find_values(std::uint64_t set, const Shooter& shooter, const PointBlock& block,
                   const PartMask* masks, double* values);
  void store_values(std::uint64_t set, const Shooter& shooter, const PointBlock& block,
                    const PartMask* masks, const double* values);
  // Drops every answer of a set (it is being destroyed).
  void forget_set(std::uint64_t set);

  std::size_t bytes() const { return bytes_; }  // held now, keys and answers
  std::size_t peak_bytes() const { return peak_bytes_; }
  std::size_t budget() const { return budget_; }
  std::uint64_t hits() const { return hits_; }
  std::uint64_t misses() const { return misses_; }
  std::size_t entries() const { return std::size_t(records_); }  // records held

  // A fresh id for a set of occluders (process-wide, never reused).
  static std::uint64_t new_set_id();

 private:
  // Keys are kept once however many sets and shooters use them: the V shares of a group are
  // asked about the same block for the same shooter, and every shot of a run asks about the
  // same blocks (keys question_key.h, with their hash).
  struct Block {
    std::uint64_t hash;
    BlockKey key;
    int users = 0;  // slots using it
  };
  // How often a shooter was shot and when last: a shot is a question about the first (set,
  // block) the cache saw for that shooter. Kept for the cache's life (a few dozen bytes per
  // patch shot, outside the budget), so a shooter shot often stays known when its answers
  // went.
  struct Use {
    std::uint64_t shots = 0, last = 0;
    std::uint64_t first_set = 0, first_block = 0;  // its first question (set, block hash)
  };
  // All answers to one shooter's questions about one block, as records in one array of
  // words (record_layout in answer_cache.cpp): one per set, and the values records.
  struct Slot {
    Block* block;
    std::vector<std::uint64_t> words;
  };
  struct Target {
    std::uint64_t hash;
    ShooterKey key;
    Use* use;
    std::list<Slot> slots;  // oldest first
  };
  struct Key {
    const Target* target;
    const Block* block;
    bool operator==(const Key& o) const { return target == o.target && block == o.block; }
  };
  struct KeyHash {
    std::size_t operator()(const Key& k) const;
  };

  // The block with these points and patches (bit for bit), or null; `hash`: its hash.
  Block* find_block(const PointBlock& block, std::uint64_t& hash) const;
  // The shooter's target, or null; `hash`: the shooter's hash.
  Target* find_target(const Shooter& shooter, std::uint64_t& hash) const;
  // A question for `set` about this shooter and block: counts the shooter's use, and
  // returns the first word of the set's record of `kind` (null: none held).
  const std::uint64_t* find_record(std::uint64_t set, int kind, const Shooter& shooter,
                                   const PointBlock& block);
  // Keeps `record` (the words of one record) for the shooter and block unless the set has
  // one of that kind there already.
  void insert(std::vector<std::uint64_t> record, const Shooter& shooter, const PointBlock& block);
  // Drops the slot (and its keys when they have no other user).
  void release(Target* target, std::list<Slot>::iterator slot);
  // Drops slots until at most `bytes` are held: those of the shooter shot least often (and
  // least recently among equals) first, and `keep`'s only when no other's are left.
  void evict_until(std::size_t bytes, const Target* keep);
  std::size_t slot_bytes(const Slot& slot) const;

  std::size_t budget_;
  std::size_t bytes_ = 0, peak_bytes_ = 0;
  std::uint64_t hits_ = 0, misses_ = 0, records_ = 0, clock_ = 0;
  std::unordered_multimap<std::uint64_t, std::unique_ptr<Block>> blocks_;
  std::unordered_multimap<std::uint64_t, std::unique_ptr<Target>> targets_;
  std::unordered_map<std::uint64_t, Use> uses_;  // by shooter hash
  mutable Target* last_target_ = nullptr;
  mutable std::array<Block*, 16> recent_blocks_{};
  mutable std::size_t next_recent_ = 0;
  std::unordered_map<Key, std::list<Slot>::iterator, KeyHash> index_;
  std::mutex mutex_;
};

}  // namespace ncube

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

#include "host/host_side.h"
#include "host/question_key.h"
#include "radiosity/shooter.h"
#include "radiosity/work_counts.h"

namespace ncube {

class AnswerCache {
 public:
  // Choice: 512 MiB by default; every answer and form factor of the scene2 run at R=8, V=7
  // takes about 300 MB (docs/performance.md); NCUBE_ANSWER_CACHE_MB overrides it (0 turns
  // the cache off).
  static std::size_t default_budget_bytes();

  explicit AnswerCache(std::size_t budget_bytes);
  AnswerCache(const AnswerCache&) = delete;
  AnswerCache& operator=(const AnswerCache&) = delete;

  // When set `set` (an id no other set ever had) was asked about exactly this block for
  // this shooter before and its answers are still held: writes them to masks[0 .. count),
  // adds the block's counts to `counts` and returns true.
  bool find(std::uint64_t set, const Shooter& shooter, const PointBlock& block, PartMask* masks,
            WorkCounts& counts);
  // Remembers masks[0 .. count) and the block's counts (the least recently used answers go
  // when over budget; answers larger than the whole budget are not kept).
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
  std::size_t entries() const { return lru_.size(); }

  // A fresh id for a set of occluders (process-wide, never reused).
  static std::uint64_t new_set_id();

 private:
  // Keys are kept once however many sets are asked about them: the V shares of a group are
  // asked about the same block for the same shooter.
  // Keys (question_key.h) with their hash and the number of entries using them.
  struct Block {
    std::uint64_t hash;
    BlockKey key;
    int users = 0;
  };
  struct Target {
    std::uint64_t hash;
    ShooterKey key;
    int users = 0;
  };
  // Most answers are "every part visible" or "none": two bits per point say which, and
  // only the other masks are kept (0: none, 1: all parts, 2: the next of `partial`).
  struct Entry {
    std::uint64_t set;
    Target* target;
    Block* block;
    std::vector<std::uint64_t> codes;  // 32 points per word
    std::vector<PartMask> partial;
    WorkCounts counts;
    std::vector<PartMask> masks;  // values entries: the masks they were computed from
    std::vector<double> values;
    std::size_t bytes;
  };
  struct Key {
    std::uint64_t set;
    const Target* target;
    const Block* block;
    bool operator==(const Key& o) const {
      return set == o.set && target == o.target && block == o.block;
    }
  };
  struct KeyHash {
    std::size_t operator()(const Key& k) const;
  };

  // The block with these points and patches (bit for bit), or null; `hash`: its hash.
  Block* find_block(const PointBlock& block, std::uint64_t& hash) const;
  Target* find_target(const Shooter& shooter) const;
  // The entry of (set, shooter, block), or null (under mutex_).
  Entry* find_entry(std::uint64_t set, const Shooter& shooter, const PointBlock& block);
  // Keeps `entry` (its set, payload and bytes filled in) unless one is held already.
  void insert(Entry entry, const Shooter& shooter, const PointBlock& block);
  void release(Entry& entry);
  void evict_until(std::size_t bytes);

  std::size_t budget_;
  std::size_t bytes_ = 0, peak_bytes_ = 0;
  std::uint64_t hits_ = 0, misses_ = 0;
  std::unordered_multimap<std::uint64_t, std::unique_ptr<Block>> blocks_;
  std::unordered_multimap<std::uint64_t, std::unique_ptr<Target>> targets_;
  mutable Target* last_target_ = nullptr;
  mutable std::array<Block*, 16> recent_blocks_{};
  mutable std::size_t next_recent_ = 0;
  std::list<Entry> lru_;  // most recently used first
  std::unordered_map<Key, std::list<Entry>::iterator, KeyHash> index_;
  std::mutex mutex_;
};

}  // namespace ncube

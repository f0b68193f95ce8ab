#include "host/answer_cache.h"

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <cstring>

namespace ncube {
namespace {

// What a node of a standard container costs besides its element (pointers, hash, malloc's
// header): counted with every slot and key so that the budget bounds the real footprint.
constexpr std::size_t kNodeOverhead = 64;

// A record, in 64-bit words (a slot holds one per set asked, one after the other):
//   set id; header (kind in bits 0-1, points n in bits 2-32, partial masks p from bit 33);
//   the masks' codes, 2 bits per point, 32 points per word: 0 none visible, 1 all parts,
//   2 the next of the p partial masks that follow (most answers are all or none);
//   answers (kind 0): a bitmap of the nonzero counters (NCUBE_WORK_COUNTERS order), then
//   their values; values (kind 1): the n values' bits.
constexpr int kAnswers = 0, kValues = 1;

std::size_t code_words(std::size_t n) { return (n + 31) / 32; }
std::size_t points_of(const std::uint64_t* record) { return std::size_t(record[1] >> 2 & 0x7fffffffu); }
std::size_t partials_of(const std::uint64_t* record) { return std::size_t(record[1] >> 33); }
int kind_of(const std::uint64_t* record) { return int(record[1] & 3u); }

// The record's words after its masks.
const std::uint64_t* payload(const std::uint64_t* record) {
  return record + 2 + code_words(points_of(record)) + partials_of(record);
}

std::size_t record_length(const std::uint64_t* record) {
  const std::uint64_t* rest = payload(record);
  const std::size_t tail = kind_of(record) == kAnswers
                               ? 1 + std::size_t(__builtin_popcountll(rest[0]))
                               : points_of(record);
  return std::size_t(rest - record) + tail;
}

// A new record's set, header and masks.
std::vector<std::uint64_t> begin_record(std::uint64_t set, int kind, const PartMask* masks,
                                        std::size_t count, PartMask all) {
  std::vector<std::uint64_t> codes(code_words(count), 0), partial;
  for (std::size_t k = 0; k < count; ++k) {
    const PartMask m = masks[k];
    const std::uint64_t code = m == 0 ? 0 : (m == all ? 1 : 2);
    codes[k / 32] |= code << (2 * (k % 32));
    if (code == 2) partial.push_back(m);
  }
  std::vector<std::uint64_t> record{set, std::uint64_t(kind) | std::uint64_t(count) << 2 |
                                             std::uint64_t(partial.size()) << 33};
  record.insert(record.end(), codes.begin(), codes.end());
  record.insert(record.end(), partial.begin(), partial.end());
  return record;
}

void decode_masks(const std::uint64_t* record, PartMask all, PartMask* masks) {
  const std::size_t count = points_of(record);
  const std::uint64_t* codes = record + 2;
  const std::uint64_t* partial = codes + code_words(count);
  for (std::size_t k = 0; k < count; ++k) {
    const unsigned code = unsigned(codes[k / 32] >> (2 * (k % 32))) & 3u;
    masks[k] = code == 0 ? 0 : (code == 1 ? all : *partial++);
  }
}

void append_counts(const WorkCounts& counts, std::vector<std::uint64_t>& record) {
  const std::size_t bitmap_at = record.size();
  record.push_back(0);
  std::uint64_t bitmap = 0;
  int index = 0;
#define NCUBE_PACK(member, cost, doc)        \
  if (counts.member != 0) {                  \
    bitmap |= std::uint64_t(1) << index;     \
    record.push_back(counts.member);         \
  }                                          \
  ++index;
  NCUBE_WORK_COUNTERS(NCUBE_PACK)
#undef NCUBE_PACK
  record[bitmap_at] = bitmap;
}

void add_counts(const std::uint64_t* packed, WorkCounts& counts) {
  const std::uint64_t bitmap = *packed++;
  int index = 0;
#define NCUBE_UNPACK(member, cost, doc) \
  if (bitmap >> index & 1) counts.member += *packed++; \
  ++index;
  NCUBE_WORK_COUNTERS(NCUBE_UNPACK)
#undef NCUBE_UNPACK
}

}  // namespace

std::size_t AnswerCache::default_budget_bytes() {
  std::size_t megabytes = 384;
  if (const char* text = std::getenv("NCUBE_ANSWER_CACHE_MB")) {
    char* end = nullptr;
    const unsigned long long value = std::strtoull(text, &end, 10);
    if (end != text && *end == '\0') megabytes = std::size_t(value);
  }
  return megabytes << 20;
}

std::uint64_t AnswerCache::new_set_id() {
  static std::atomic<std::uint64_t> next{1};
  return next++;
}

AnswerCache::AnswerCache(std::size_t budget_bytes) : budget_(budget_bytes) {}

std::size_t AnswerCache::KeyHash::operator()(const Key& k) const {
  std::uint64_t h = std::uint64_t(reinterpret_cast<std::uintptr_t>(k.target)) * 0x9e3779b97f4a7c15ull;
  h ^= std::uint64_t(reinterpret_cast<std::uintptr_t>(k.block)) + (h << 6) + (h >> 2);
  return std::size_t(h);
}

std::size_t AnswerCache::slot_bytes(const Slot& slot) const {
  return sizeof(Slot) + 2 * kNodeOverhead + slot.words.capacity() * sizeof(std::uint64_t);
}

AnswerCache::Block* AnswerCache::find_block(const PointBlock& block, std::uint64_t& hash) const {
  // The V shares of a group are asked about the same block one after the other: the
  // blocks found last are compared first (blocks of other groups differ at their first point).
  for (Block* b : recent_blocks_)
    if (b && b->key.is(block)) {
      hash = b->hash;
      return b;
    }
  hash = question_hash(block);
  auto [begin, end] = blocks_.equal_range(hash);
  for (auto it = begin; it != end; ++it)
    if (it->second->key.is(block)) {
      recent_blocks_[next_recent_++ % recent_blocks_.size()] = it->second.get();
      return it->second.get();
    }
  return nullptr;
}

AnswerCache::Target* AnswerCache::find_target(const Shooter& shooter, std::uint64_t& hash) const {
  // Every block of a shot has the same shooter: the last one found is compared first.
  if (last_target_ && last_target_->key.is(shooter)) {
    hash = last_target_->hash;
    return last_target_;
  }
  hash = question_hash(shooter);
  auto [begin, end] = targets_.equal_range(hash);
  for (auto it = begin; it != end; ++it)
    if (it->second->key.is(shooter)) return last_target_ = it->second.get();
  return nullptr;
}

const std::uint64_t* AnswerCache::find_record(std::uint64_t set, int kind, const Shooter& shooter,
                                              const PointBlock& points) {
  std::uint64_t block_hash, target_hash;
  const Block* block = find_block(points, block_hash);
  const Target* target = find_target(shooter, target_hash);
  // The shooter's use: its first question marks a shot.
  Use& use = uses_[target_hash];
  if (use.shots == 0) {
    use.first_set = set;
    use.first_block = block_hash;
  }
  ++clock_;
  if (use.first_set == set && use.first_block == block_hash) ++use.shots;
  use.last = clock_;
  if (block && target) {
    const auto it = index_.find(Key{target, block});
    if (it != index_.end()) {
      const std::vector<std::uint64_t>& words = it->second->words;
      for (std::size_t at = 0; at < words.size(); at += record_length(words.data() + at))
        if (words[at] == set && kind_of(words.data() + at) == kind) {
          ++hits_;
          return words.data() + at;
        }
    }
  }
  ++misses_;
  return nullptr;
}

bool AnswerCache::find(std::uint64_t set, const Shooter& shooter, const PointBlock& block,
                       PartMask* masks, WorkCounts& counts) {
  if (budget_ == 0) return false;
  const std::lock_guard<std::mutex> lock(mutex_);
  const std::uint64_t* record = find_record(set, kAnswers, shooter, block);
  if (!record || points_of(record) != block.count) return false;
  decode_masks(record, shooter.all_parts(), masks);
  add_counts(payload(record), counts);
  return true;
}

bool AnswerCache::find_values(std::uint64_t set, const Shooter& shooter, const PointBlock& block,
                              const PartMask* masks, double* values) {
  if (budget_ == 0) return false;
  const std::lock_guard<std::mutex> lock(mutex_);
  const std::uint64_t* record = find_record(set, kValues, shooter, block);
  const std::size_t count = block.count;
  if (!record || points_of(record) != count) return false;
  std::vector<PartMask> held(count);  // the masks they were computed from, compared in full
  decode_masks(record, shooter.all_parts(), held.data());
  if (!std::equal(masks, masks + count, held.begin())) return false;
  std::memcpy(values, payload(record), count * sizeof(double));
  return true;
}

void AnswerCache::store(std::uint64_t set, const Shooter& shooter, const PointBlock& block,
                        const PartMask* masks, const WorkCounts& counts) {
  if (budget_ == 0) return;
  std::vector<std::uint64_t> record =
      begin_record(set, kAnswers, masks, block.count, shooter.all_parts());
  append_counts(counts, record);
  insert(std::move(record), shooter, block);
}

void AnswerCache::store_values(std::uint64_t set, const Shooter& shooter, const PointBlock& block,
                               const PartMask* masks, const double* values) {
  if (budget_ == 0) return;
  const std::size_t count = block.count;
  std::vector<std::uint64_t> record = begin_record(set, kValues, masks, count, shooter.all_parts());
  const std::size_t at = record.size();
  record.resize(at + count);
  std::memcpy(record.data() + at, values, count * sizeof(double));
  insert(std::move(record), shooter, block);
}

void AnswerCache::insert(std::vector<std::uint64_t> record, const Shooter& shooter,
                         const PointBlock& points) {
  const std::size_t count = points.count;
  const std::size_t record_bytes = record.size() * sizeof(std::uint64_t);
  const std::size_t new_slot_bytes = sizeof(Slot) + 2 * kNodeOverhead;
  const std::size_t block_bytes =
      sizeof(Block) + kNodeOverhead + count * (sizeof(Vec3) + sizeof(int));
  const std::size_t target_bytes =
      sizeof(Target) + kNodeOverhead + std::size_t(shooter.part_count) * sizeof(Vec3);
  if (record_bytes + new_slot_bytes + block_bytes + target_bytes > budget_) return;
  const std::lock_guard<std::mutex> lock(mutex_);
  std::uint64_t block_hash, target_hash;
  Block* block = find_block(points, block_hash);
  Target* target = find_target(shooter, target_hash);
  auto slot_of = [&]() -> Slot* {
    if (!block || !target) return nullptr;
    const auto it = index_.find(Key{target, block});
    return it == index_.end() ? nullptr : &*it->second;
  };
  Slot* slot = slot_of();
  if (slot)  // held already?
    for (std::size_t at = 0; at < slot->words.size(); at += record_length(slot->words.data() + at))
      if (slot->words[at] == record[0] && kind_of(slot->words.data() + at) == kind_of(record.data()))
        return;
  // Make room first; the keys found may go with the slots evicted, and then need room too.
  for (;;) {
    const std::size_t needed = record_bytes + (slot ? 0 : new_slot_bytes) +
                               (block ? 0 : block_bytes) + (target ? 0 : target_bytes);
    if (bytes_ + needed <= budget_) break;
    // Room for more than this record: the victim is chosen by a scan of the shooters.
    evict_until(budget_ - std::min(budget_, needed + budget_ / 64), target);
    block = find_block(points, block_hash);
    target = find_target(shooter, target_hash);
    slot = slot_of();
  }
  if (!block) {
    auto b = std::make_unique<Block>();
    b->hash = block_hash;
    b->key = BlockKey(points);
    block = b.get();
    blocks_.emplace(block_hash, std::move(b));
    recent_blocks_[next_recent_++ % recent_blocks_.size()] = block;
    bytes_ += block_bytes;
  }
  if (!target) {
    auto t = std::make_unique<Target>();
    t->hash = target_hash;
    t->key = ShooterKey(shooter);
    t->use = &uses_[target_hash];
    target = t.get();
    targets_.emplace(target_hash, std::move(t));
    bytes_ += target_bytes;
  }
  if (!slot) {
    target->slots.push_back(Slot{block, {}});
    ++block->users;
    index_.emplace(Key{target, block}, std::prev(target->slots.end()));
    slot = &target->slots.back();
    bytes_ += slot_bytes(*slot);
  }
  // Appended in place, the array's capacity exactly its size (no room wasted by doubling).
  bytes_ -= slot_bytes(*slot);
  std::vector<std::uint64_t> words;
  words.reserve(slot->words.size() + record.size());
  words.insert(words.end(), slot->words.begin(), slot->words.end());
  words.insert(words.end(), record.begin(), record.end());
  slot->words = std::move(words);
  bytes_ += slot_bytes(*slot);
  ++records_;
  if (bytes_ > peak_bytes_) peak_bytes_ = bytes_;
}

void AnswerCache::release(Target* target, std::list<Slot>::iterator slot) {
  for (std::size_t at = 0; at < slot->words.size(); at += record_length(slot->words.data() + at))
    --records_;
  bytes_ -= slot_bytes(*slot);
  Block* block = slot->block;
  index_.erase(Key{target, block});
  target->slots.erase(slot);
  if (--block->users == 0) {
    for (Block*& recent : recent_blocks_)
      if (recent == block) recent = nullptr;
    auto [begin, end] = blocks_.equal_range(block->hash);
    for (auto it = begin; it != end; ++it)
      if (it->second.get() == block) {
        bytes_ -= sizeof(Block) + kNodeOverhead + block->key.bytes();
        blocks_.erase(it);
        break;
      }
  }
  if (target->slots.empty()) {
    if (last_target_ == target) last_target_ = nullptr;
    auto [begin, end] = targets_.equal_range(target->hash);
    for (auto it = begin; it != end; ++it)
      if (it->second.get() == target) {
        bytes_ -= sizeof(Target) + kNodeOverhead + target->key.bytes();
        targets_.erase(it);
        break;
      }
  }
}

void AnswerCache::evict_until(std::size_t bytes, const Target* keep) {
  while (bytes_ > bytes) {
    Target* victim = nullptr;
    for (const auto& [hash, t] : targets_) {
      if (t.get() == keep) continue;
      const Use& u = *t->use;
      if (!victim || u.shots < victim->use->shots ||
          (u.shots == victim->use->shots && u.last < victim->use->last))
        victim = t.get();
    }
    if (!victim) {  // only the shooter being stored holds answers: its oldest go
      for (const auto& [hash, t] : targets_)
        if (t.get() == keep) victim = t.get();
      if (!victim) return;
    }
    // Its oldest slots first, until enough room or none left (then the target goes too).
    while (bytes_ > bytes) {
      const bool last = victim->slots.size() == 1;
      release(victim, victim->slots.begin());
      if (last) break;
    }
  }
}

void AnswerCache::forget_set(std::uint64_t set) {
  const std::lock_guard<std::mutex> lock(mutex_);
  std::vector<Target*> targets;
  for (const auto& [hash, t] : targets_) targets.push_back(t.get());
  for (Target* target : targets) {
    for (auto slot = target->slots.begin(); slot != target->slots.end();) {
      std::vector<std::uint64_t> kept;
      std::size_t dropped = 0;
      const std::vector<std::uint64_t>& words = slot->words;
      for (std::size_t at = 0; at < words.size();) {
        const std::size_t length = record_length(words.data() + at);
        if (words[at] == set)
          ++dropped;
        else
          kept.insert(kept.end(), words.begin() + std::ptrdiff_t(at), words.begin() + std::ptrdiff_t(at + length));
        at += length;
      }
      const auto next = std::next(slot);
      if (dropped > 0) {
        if (kept.empty()) {
          const bool last = target->slots.size() == 1;
          release(target, slot);
          if (last) break;  // the target is gone
        } else {
          bytes_ -= slot_bytes(*slot);
          kept.shrink_to_fit();
          slot->words = std::move(kept);
          bytes_ += slot_bytes(*slot);
          records_ -= dropped;
        }
      }
      slot = next;
    }
  }
}

}  // namespace ncube

#include "host/answer_cache.h"

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <cstring>

namespace ncube {
namespace {

// What a node of a standard container costs besides its element (pointers, hash, malloc's
// header): counted with every entry and key so that the budget bounds the real footprint.
constexpr std::size_t kNodeOverhead = 64;

}  // namespace

std::size_t AnswerCache::default_budget_bytes() {
  std::size_t megabytes = 512;
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
  std::uint64_t h = k.set * 0x9e3779b97f4a7c15ull;
  h ^= std::uint64_t(reinterpret_cast<std::uintptr_t>(k.target)) + (h << 6) + (h >> 2);
  h ^= std::uint64_t(reinterpret_cast<std::uintptr_t>(k.block)) + (h << 6) + (h >> 2);
  return std::size_t(h);
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

AnswerCache::Target* AnswerCache::find_target(const Shooter& shooter) const {
  // Every block of a shot has the same shooter: the last one found is compared first.
  if (last_target_ && last_target_->key.is(shooter)) return last_target_;
  auto [begin, end] = targets_.equal_range(question_hash(shooter));
  for (auto it = begin; it != end; ++it)
    if (it->second->key.is(shooter)) return last_target_ = it->second.get();
  return nullptr;
}

AnswerCache::Entry* AnswerCache::find_entry(std::uint64_t set, const Shooter& shooter,
                                             const PointBlock& points) {
  std::uint64_t block_hash;
  const Block* block = find_block(points, block_hash);
  const Target* target = block ? find_target(shooter) : nullptr;
  const auto it = target ? index_.find(Key{set, target, block}) : index_.end();
  if (it == index_.end()) {
    ++misses_;
    return nullptr;
  }
  ++hits_;
  lru_.splice(lru_.begin(), lru_, it->second);  // most recently used first
  return &*it->second;
}

bool AnswerCache::find(std::uint64_t set, const Shooter& shooter, const PointBlock& block,
                       PartMask* masks, WorkCounts& counts) {
  if (budget_ == 0) return false;
  const std::lock_guard<std::mutex> lock(mutex_);
  const Entry* entry = find_entry(set, shooter, block);
  const std::size_t count = block.count;
  if (!entry) return false;
  const PartMask all = shooter.all_parts();
  std::size_t next = 0;
  for (std::size_t k = 0; k < count; ++k) {
    const unsigned code = unsigned(entry->codes[k / 32] >> (2 * (k % 32))) & 3u;
    masks[k] = code == 0 ? 0 : (code == 1 ? all : entry->partial[next++]);
  }
  counts += entry->counts;
  return true;
}

bool AnswerCache::find_values(std::uint64_t set, const Shooter& shooter, const PointBlock& block,
                              const PartMask* masks, double* values) {
  if (budget_ == 0) return false;
  const std::lock_guard<std::mutex> lock(mutex_);
  const Entry* entry = find_entry(set, shooter, block);
  const std::size_t count = block.count;
  if (!entry || entry->values.size() != count || !std::equal(masks, masks + count, entry->masks.begin()))
    return false;
  std::copy(entry->values.begin(), entry->values.end(), values);
  return true;
}

void AnswerCache::store(std::uint64_t set, const Shooter& shooter, const PointBlock& block,
                        const PartMask* masks, const WorkCounts& counts) {
  const std::size_t count = block.count;
  const PartMask all = shooter.all_parts();
  Entry entry{};
  entry.set = set;
  entry.codes.assign((count + 31) / 32, 0);
  for (std::size_t k = 0; k < count; ++k) {
    const PartMask m = masks[k];
    const std::uint64_t code = m == 0 ? 0 : (m == all ? 1 : 2);
    entry.codes[k / 32] |= code << (2 * (k % 32));
    if (code == 2) entry.partial.push_back(m);
  }
  entry.partial.shrink_to_fit();
  entry.counts = counts;
  entry.bytes = sizeof(Entry) + 2 * kNodeOverhead + entry.codes.size() * sizeof(std::uint64_t) +
                entry.partial.size() * sizeof(PartMask);
  insert(std::move(entry), shooter, block);
}

void AnswerCache::store_values(std::uint64_t set, const Shooter& shooter, const PointBlock& block,
                               const PartMask* masks, const double* values) {
  const std::size_t count = block.count;
  Entry entry{};
  entry.set = set;
  entry.masks.assign(masks, masks + count);
  entry.values.assign(values, values + count);
  entry.bytes = sizeof(Entry) + 2 * kNodeOverhead + count * (sizeof(PartMask) + sizeof(double));
  insert(std::move(entry), shooter, block);
}

void AnswerCache::insert(Entry entry, const Shooter& shooter, const PointBlock& points) {
  const std::size_t count = points.count;
  const std::size_t entry_bytes = entry.bytes;
  const std::size_t block_bytes =
      sizeof(Block) + kNodeOverhead + count * (sizeof(Vec3) + sizeof(int));
  const std::size_t target_bytes =
      sizeof(Target) + kNodeOverhead + std::size_t(shooter.part_count) * sizeof(Vec3);
  if (budget_ == 0 || entry_bytes + block_bytes + target_bytes > budget_) return;
  const std::lock_guard<std::mutex> lock(mutex_);
  std::uint64_t block_hash;
  Block* block = find_block(points, block_hash);
  Target* target = find_target(shooter);
  if (block && target && index_.count(Key{entry.set, target, block})) return;  // held already
  // Make room first; the keys found may go with the entries evicted, and then need room too.
  for (;;) {
    const std::size_t needed = entry_bytes + (block ? 0 : block_bytes) + (target ? 0 : target_bytes);
    if (bytes_ + needed <= budget_) break;
    evict_until(budget_ - needed);
    block = find_block(points, block_hash);
    target = find_target(shooter);
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
    const std::uint64_t target_hash = question_hash(shooter);
    auto t = std::make_unique<Target>();
    t->hash = target_hash;
    t->key = ShooterKey(shooter);
    target = t.get();
    targets_.emplace(target_hash, std::move(t));
    bytes_ += target_bytes;
  }
  ++block->users;
  ++target->users;
  entry.target = target;
  entry.block = block;
  const Key key{entry.set, target, block};
  lru_.push_front(std::move(entry));
  index_.emplace(key, lru_.begin());
  bytes_ += entry_bytes;
  if (bytes_ > peak_bytes_) peak_bytes_ = bytes_;
}

void AnswerCache::release(Entry& entry) {
  index_.erase(Key{entry.set, entry.target, entry.block});
  bytes_ -= entry.bytes;
  if (--entry.block->users == 0) {
    auto [begin, end] = blocks_.equal_range(entry.block->hash);
    for (Block*& recent : recent_blocks_)
      if (recent == entry.block) recent = nullptr;
    for (auto it = begin; it != end; ++it)
      if (it->second.get() == entry.block) {
        bytes_ -= sizeof(Block) + kNodeOverhead +
                  entry.block->key.bytes();
        blocks_.erase(it);
        break;
      }
  }
  if (--entry.target->users == 0) {
    if (last_target_ == entry.target) last_target_ = nullptr;
    auto [begin, end] = targets_.equal_range(entry.target->hash);
    for (auto it = begin; it != end; ++it)
      if (it->second.get() == entry.target) {
        bytes_ -= sizeof(Target) + kNodeOverhead + entry.target->key.bytes();
        targets_.erase(it);
        break;
      }
  }
}

void AnswerCache::evict_until(std::size_t bytes) {
  while (bytes_ > bytes && !lru_.empty()) {
    release(lru_.back());
    lru_.pop_back();
  }
}

void AnswerCache::forget_set(std::uint64_t set) {
  const std::lock_guard<std::mutex> lock(mutex_);
  for (auto it = lru_.begin(); it != lru_.end();) {
    if (it->set == set) {
      release(*it);
      it = lru_.erase(it);
    } else {
      ++it;
    }
  }
}

}  // namespace ncube

#include "radiosity/answer_cache.h"

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <cstring>

namespace ncube {
namespace {

// What a node of a standard container costs besides its element (pointers, hash, malloc's
// header): counted with every entry and key so that the budget bounds the real footprint.
constexpr std::size_t kNodeOverhead = 64;

std::uint64_t mix(std::uint64_t h, std::uint64_t word) {
  h ^= word + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
  h *= 0xbf58476d1ce4e5b9ull;
  return h ^ (h >> 31);
}

std::uint64_t bits_of(double x) {
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

}  // namespace

std::uint64_t hash_points(const Vec3* points, const int* patches, std::size_t count) {
  std::uint64_t h = mix(0, count);
  for (std::size_t k = 0; k < count; ++k) {
    h = mix(h, bits_of(points[k].x));
    h = mix(h, bits_of(points[k].y));
    h = mix(h, bits_of(points[k].z));
    h = mix(h, std::uint64_t(std::uint32_t(patches[k])));
  }
  return h;
}

namespace {

std::uint64_t hash_shooter(const Shooter& shooter) {
  std::uint64_t h = mix(std::uint64_t(std::uint32_t(shooter.patch)), std::uint64_t(shooter.part_count));
  for (int k = 0; k < shooter.part_count; ++k) {
    h = mix(h, bits_of(shooter.targets[k].x));
    h = mix(h, bits_of(shooter.targets[k].y));
    h = mix(h, bits_of(shooter.targets[k].z));
  }
  return h;
}

// Bit for bit (not ==, which takes -0.0 for 0.0): the answers were computed from these bits.
bool same_bits(const Vec3* a, const Vec3* b, std::size_t count) {
  return std::memcmp(a, b, count * sizeof(Vec3)) == 0;
}

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
  return std::size_t(mix(mix(k.set, std::uint64_t(reinterpret_cast<std::uintptr_t>(k.target))),
                         std::uint64_t(reinterpret_cast<std::uintptr_t>(k.block))));
}

bool AnswerCache::Block::is(const Vec3* other_points, const int* other_patches,
                            std::size_t count) const {
  return points.size() == count && same_bits(points.data(), other_points, count) &&
         std::memcmp(patches.data(), other_patches, count * sizeof(int)) == 0;
}

AnswerCache::Block* AnswerCache::find_block(const Vec3* points, const int* patches,
                                            std::size_t count, std::uint64_t& hash) const {
  // The V shares of a group are asked about the same block one after the other: the
  // blocks found last are compared first (blocks of other groups differ at their first point).
  for (Block* b : recent_blocks_)
    if (b && b->is(points, patches, count)) {
      hash = b->hash;
      return b;
    }
  hash = hash_points(points, patches, count);
  auto [begin, end] = blocks_.equal_range(hash);
  for (auto it = begin; it != end; ++it)
    if (it->second->is(points, patches, count)) {
      recent_blocks_[next_recent_++ % recent_blocks_.size()] = it->second.get();
      return it->second.get();
    }
  return nullptr;
}

bool AnswerCache::Target::is(const Shooter& shooter) const {
  return patch == shooter.patch && part_count == shooter.part_count &&
         same_bits(targets.data(), shooter.targets.data(), std::size_t(part_count));
}

AnswerCache::Target* AnswerCache::find_target(const Shooter& shooter) const {
  // Every block of a shot has the same shooter: the last one found is compared first.
  if (last_target_ && last_target_->is(shooter)) return last_target_;
  auto [begin, end] = targets_.equal_range(hash_shooter(shooter));
  for (auto it = begin; it != end; ++it)
    if (it->second->is(shooter)) return last_target_ = it->second.get();
  return nullptr;
}

AnswerCache::Entry* AnswerCache::find_entry(std::uint64_t set, const Shooter& shooter,
                                             const Vec3* points, const int* receiver_patches,
                                             std::size_t count) {
  std::uint64_t block_hash;
  const Block* block = find_block(points, receiver_patches, count, block_hash);
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

bool AnswerCache::find(std::uint64_t set, const Shooter& shooter, const Vec3* points,
                       const int* receiver_patches, std::size_t count, PartMask* masks,
                       WorkCounts& counts) {
  if (budget_ == 0) return false;
  const std::lock_guard<std::mutex> lock(mutex_);
  const Entry* entry = find_entry(set, shooter, points, receiver_patches, count);
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

bool AnswerCache::find_values(std::uint64_t set, const Shooter& shooter, const Vec3* points,
                              const int* receiver_patches, std::size_t count,
                              const PartMask* masks, double* values) {
  if (budget_ == 0) return false;
  const std::lock_guard<std::mutex> lock(mutex_);
  const Entry* entry = find_entry(set, shooter, points, receiver_patches, count);
  if (!entry || entry->values.size() != count || !std::equal(masks, masks + count, entry->masks.begin()))
    return false;
  std::copy(entry->values.begin(), entry->values.end(), values);
  return true;
}

void AnswerCache::store(std::uint64_t set, const Shooter& shooter, const Vec3* points,
                        const int* receiver_patches, std::size_t count, const PartMask* masks,
                        const WorkCounts& counts) {
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
  insert(std::move(entry), shooter, points, receiver_patches, count);
}

void AnswerCache::store_values(std::uint64_t set, const Shooter& shooter, const Vec3* points,
                               const int* receiver_patches, std::size_t count,
                               const PartMask* masks, const double* values) {
  Entry entry{};
  entry.set = set;
  entry.masks.assign(masks, masks + count);
  entry.values.assign(values, values + count);
  entry.bytes = sizeof(Entry) + 2 * kNodeOverhead + count * (sizeof(PartMask) + sizeof(double));
  insert(std::move(entry), shooter, points, receiver_patches, count);
}

void AnswerCache::insert(Entry entry, const Shooter& shooter, const Vec3* points,
                         const int* receiver_patches, std::size_t count) {
  const std::size_t entry_bytes = entry.bytes;
  const std::size_t block_bytes =
      sizeof(Block) + kNodeOverhead + count * (sizeof(Vec3) + sizeof(int));
  const std::size_t target_bytes =
      sizeof(Target) + kNodeOverhead + std::size_t(shooter.part_count) * sizeof(Vec3);
  if (budget_ == 0 || entry_bytes + block_bytes + target_bytes > budget_) return;
  const std::lock_guard<std::mutex> lock(mutex_);
  std::uint64_t block_hash;
  Block* block = find_block(points, receiver_patches, count, block_hash);
  Target* target = find_target(shooter);
  if (block && target && index_.count(Key{entry.set, target, block})) return;  // held already
  // Make room first; the keys found may go with the entries evicted, and then need room too.
  for (;;) {
    const std::size_t needed = entry_bytes + (block ? 0 : block_bytes) + (target ? 0 : target_bytes);
    if (bytes_ + needed <= budget_) break;
    evict_until(budget_ - needed);
    block = find_block(points, receiver_patches, count, block_hash);
    target = find_target(shooter);
  }
  if (!block) {
    auto b = std::make_unique<Block>();
    b->hash = block_hash;
    b->points.assign(points, points + count);
    b->patches.assign(receiver_patches, receiver_patches + count);
    block = b.get();
    blocks_.emplace(block_hash, std::move(b));
    recent_blocks_[next_recent_++ % recent_blocks_.size()] = block;
    bytes_ += block_bytes;
  }
  if (!target) {
    const std::uint64_t target_hash = hash_shooter(shooter);
    auto t = std::make_unique<Target>();
    t->hash = target_hash;
    t->patch = shooter.patch;
    t->part_count = shooter.part_count;
    t->targets.assign(shooter.targets.begin(), shooter.targets.begin() + shooter.part_count);
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
                  entry.block->points.size() * (sizeof(Vec3) + sizeof(int));
        blocks_.erase(it);
        break;
      }
  }
  if (--entry.target->users == 0) {
    if (last_target_ == entry.target) last_target_ = nullptr;
    auto [begin, end] = targets_.equal_range(entry.target->hash);
    for (auto it = begin; it != end; ++it)
      if (it->second.get() == entry.target) {
        bytes_ -= sizeof(Target) + kNodeOverhead + entry.target->targets.size() * sizeof(Vec3);
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

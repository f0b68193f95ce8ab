#include "host/lookahead.h"

#include <algorithm>
#include <pthread.h>

#include "host/answer_cache.h"
#include "radiosity/radiosity_engine.h"

namespace ncube {

// One block of a posted shot: points_[first .. first + count) of its shot.
struct Lookahead::Block {
  enum State { kNotStarted, kStarted, kDone };
  std::atomic<int> state{kNotStarted};
  std::size_t first = 0, count = 0;
  std::uint64_t hash = 0;
  // Written by the thread that computes the block, read by the others once state is kDone.
  std::vector<PartMask> answers;   // share-major: answers[s * count + k]
  std::vector<WorkCounts> counts;  // per share
  std::vector<PartMask> visible;   // the AND of the shares' answers
  std::vector<double> form_factors;
};


Lookahead::Lookahead(const Scene& scene, std::vector<const FastOccluders*> shares, int workers)
    : Lookahead(scene, std::move(shares), {}, workers) {}

Lookahead::Lookahead(const Scene& scene, std::vector<const FastOctree*> shares, int workers)
    : Lookahead(scene, {}, std::move(shares), workers) {}

Lookahead::Lookahead(const Scene& scene, std::vector<const FastOccluders*> brute_force,
                     std::vector<const FastOctree*> octrees, int workers)
    : ThreadedAssist(std::max(1, workers) + 1, nullptr),
      scene_(scene),
      shares_(std::move(brute_force)),
      octree_shares_(std::move(octrees)),
      blockers_(SceneBlockers::for_scene(scene)),
      form_factor_set_(AnswerCache::new_set_id()),
      unshot_power_(scene.patches.size(), 0.0),
      posted_patch_(scene.patches.size(), 0),
      guessed_patch_(scene.patches.size(), 0) {
  sets_.assign(shares_.begin(), shares_.end());
  sets_.insert(sets_.end(), octree_shares_.begin(), octree_shares_.end());
  for (int w = 0; w < std::max(1, workers); ++w)
    threads_.emplace_back([this] {
      pthread_setname_np(pthread_self(), "lookahead");  // as profilers and top show it
      work();
    });
}

Lookahead::~Lookahead() {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
    active_.clear();  // the shots' handles may outlive this; their blocks are not computed
  }
  work_to_do_.notify_all();
  for (std::thread& t : threads_) t.join();
  blockers_->answer_cache().forget_set(form_factor_set_);
}

std::shared_ptr<Lookahead::Shot> Lookahead::post(const Shooter& shooter,
                                                 const std::vector<Vec3>& points,
                                                 const std::vector<int>& patches,
                                                 int block_size) {
  auto shot = std::make_shared<Shot>();
  shot->shooter_ = shooter;
  shot->key_ = ShooterKey(shooter);
  shot->points_ = points;
  shot->patches_ = patches;
  // The sides of the shooter's targets, once per share (main thread: the sets keep the last).
  for (const FastOccluders* share : shares_) shot->sides_.push_back(share->target_sides(shooter));
  const std::size_t size = std::size_t(std::max(1, block_size));
  for (std::size_t first = 0; first < points.size(); first += size) {
    auto block = std::make_unique<Block>();
    block->first = first;
    block->count = std::min(size, points.size() - first);
    block->hash = question_hash(PointBlock(points, patches).part(first, first + block->count));
    shot->blocks_.push_back(std::move(block));
  }
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (shooter.patch >= 0 && std::size_t(shooter.patch) < posted_patch_.size())
      posted_patch_[std::size_t(shooter.patch)] = 1;
    for (auto it = posted_.begin(); it != posted_.end();)  // shots nobody holds any more
      it = it->second.shot.expired() ? posted_.erase(it) : std::next(it);
    for (const auto& block : shot->blocks_) posted_.emplace(block->hash, Posted{shot, block.get()});
    if (!shot->blocks_.empty()) active_.push_back(shot);
  }
  work_to_do_.notify_all();
  return shot;
}

Lookahead::Block* Lookahead::claim_next(std::shared_ptr<Shot>& shot) {
  // The blocks are asked for in order, every group at about the same pace: the lowest
  // block index first, the oldest shot first among equals.
  for (;;) {
    Shot* best = nullptr;
    for (const auto& s : active_)
      if (!best || s->next_unclaimed_ < best->next_unclaimed_) best = s.get();
    if (!best) return nullptr;
    Block& block = *best->blocks_[best->next_unclaimed_++];
    auto it = std::find_if(active_.begin(), active_.end(),
                           [best](const std::shared_ptr<Shot>& s) { return s.get() == best; });
    shot = *it;
    if (best->next_unclaimed_ == best->blocks_.size()) active_.erase(it);
    int expected = Block::kNotStarted;
    if (block.state.compare_exchange_strong(expected, Block::kStarted)) return &block;
    shot.reset();  // a node program started it already: the next one
  }
}

void Lookahead::work() {
  for (;;) {
    std::shared_ptr<Shot> shot;
    Block* block = nullptr;
    GuessBlock guess;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      work_to_do_.wait(lock, [&] {
        return stopping_ || (block = claim_next(shot)) != nullptr || next_guess_block(guess);
      });
      if (stopping_) return;
    }
    try {
      if (block)
        compute(*shot, *block);
      else
        compute_guess(guess);
    } catch (const std::exception&) {  // not out of this thread: std::terminate would end all
      const std::lock_guard<std::mutex> lock(mutex_);
      if (!failure_) failure_ = std::current_exception();
    }
    if (block) finish(*block);
  }
}

void Lookahead::guess_shots(int samples, int block_size, int ranks) {
  const std::lock_guard<std::mutex> lock(mutex_);
  guessing_ = true;
  samples_ = samples;
  block_size_ = std::max(1, block_size);
  rank_points_.assign(std::size_t(ranks), {});
  rank_patches_.assign(std::size_t(ranks), {});
}

void Lookahead::know_receivers(int rank, std::vector<Vec3> points, std::vector<int> patches) {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (rank < 0 || std::size_t(rank) >= rank_points_.size()) return;
  rank_points_[std::size_t(rank)] = std::move(points);
  rank_patches_[std::size_t(rank)] = std::move(patches);
}

void Lookahead::know_unshot(const std::vector<std::pair<int, double>>& powers) {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    for (const auto& [patch, power] : powers)
      if (patch >= 0 && std::size_t(patch) < unshot_power_.size())
        unshot_power_[std::size_t(patch)] = power;
  }
  work_to_do_.notify_all();
}

bool Lookahead::next_guess_block(GuessBlock& block) {
  if (!guessing_) return false;
  for (;;) {
    // A guess shot for real meanwhile: its posted blocks are computed as they are asked for.
    if (guess_.shooter && posted_patch_[std::size_t(guess_.shooter->patch)]) guess_ = GuessBlock{};
    if (guess_.shooter) {
      // The next block of the guessed shot: rank by rank, as each would post it.
      while (guess_rank_ < rank_points_.size()) {
        const std::vector<Vec3>& points = rank_points_[guess_rank_];
        const std::vector<int>& patches = rank_patches_[guess_rank_];
        block.points.clear();
        block.patches.clear();
        // Skip the receivers before guess_first_ (those not on the shooter), take the next
        // block_size_ of them.
        std::size_t seen = 0;
        for (std::size_t k = 0; k < points.size() && block.points.size() < std::size_t(block_size_); ++k) {
          if (patches[k] == guess_.shooter->patch) continue;
          if (seen++ < guess_first_) continue;
          block.points.push_back(points[k]);
          block.patches.push_back(patches[k]);
        }
        if (block.points.empty()) {
          ++guess_rank_;
          guess_first_ = 0;
          continue;
        }
        guess_first_ += block.points.size();
        block.shooter = guess_.shooter;
        block.sides = guess_.sides;
        return true;
      }
      guess_ = GuessBlock{};
    }
    // A new guess: the never-shot patch with the most unshot power.
    int best = -1;
    for (std::size_t p = 0; p < unshot_power_.size(); ++p)
      if (!posted_patch_[p] && !guessed_patch_[p] && unshot_power_[p] > 0.0 &&
          (best < 0 || unshot_power_[p] > unshot_power_[std::size_t(best)]))
        best = int(p);
    if (best < 0) return false;
    guessed_patch_[std::size_t(best)] = 1;
    auto shooter = std::make_shared<Shooter>(make_shooter(scene_, best, Rgb(0.0), samples_));
    auto sides = std::make_shared<std::vector<std::shared_ptr<const FastOccluders::TargetSides>>>();
    for (const FastOccluders* share : shares_) sides->push_back(share->sides_for(*shooter));
    guess_.shooter = shooter;
    guess_.sides = sides;
    guess_rank_ = 0;
    guess_first_ = 0;
  }
}

void Lookahead::compute_guess(const GuessBlock& block) {
  const std::size_t n = block.points.size();
  std::vector<PartMask> answers(share_count() * n);
  std::vector<WorkCounts> counts(share_count());
  answer_shares(*block.shooter, *block.sides, PointBlock(block.points, block.patches),
                answers.data(), counts.data());
}

void Lookahead::answer_shares(const Shooter& shooter,
                              const std::vector<std::shared_ptr<const FastOccluders::TargetSides>>& sides,
                              const PointBlock& block, PartMask* answers, WorkCounts* counts) const {
  // Exactly what each share's batch call does (fast_octree.h: the walk; fast_occluders.h: its
  // remembered answers, or the computation from the block's scene-wide answers, computed
  // once for all shares).
  for (std::size_t s = 0; s < octree_shares_.size(); ++s)
    octree_shares_[s]->answer_block_here(block, shooter, answers + s * block.count, counts[s]);
  FastOccluders::SharedBlock shared;
  for (std::size_t s = 0; s < shares_.size(); ++s) {
    const FastOccluders& set = *shares_[s];
    PartMask* masks = answers + s * block.count;
    if (set.remembered(shooter, block, masks, counts[s])) continue;
    set.answer_block_here(block, shooter, *sides[s], shared, masks, counts[s]);
    set.remember(shooter, block, masks, counts[s]);
  }
}

void Lookahead::compute(Shot& shot, Block& block) {
  const std::size_t n = block.count;
  const PointBlock asked = PointBlock(shot.points_, shot.patches_).part(block.first, block.first + n);
  const Vec3* points = asked.points;
  const int* patches = asked.patches;
  const Shooter& shooter = shot.shooter_;
  block.answers.assign(share_count() * n, 0);
  block.counts.assign(share_count(), WorkCounts{});
  answer_shares(shooter, shot.sides_, asked, block.answers.data(), block.counts.data());
  block.visible.assign(n, shooter.all_parts());
  for (std::size_t s = 0; s < share_count(); ++s)
    for (std::size_t k = 0; k < n; ++k) block.visible[k] &= block.answers[s * n + k];
  block.form_factors.resize(n);
  AnswerCache& cache = blockers_->answer_cache();
  if (cache.find_values(form_factor_set_, shooter, asked, block.visible.data(),
                        block.form_factors.data()))
    return;
  for (std::size_t k = 0; k < n; ++k)
    block.form_factors[k] = receiver_form_factor(
        shooter, points[k], scene_.patches[std::size_t(patches[k])].normal, block.visible[k]);
  cache.store_values(form_factor_set_, shooter, asked, block.visible.data(),
                     block.form_factors.data());
}

void Lookahead::finish(Block& block) {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    block.state.store(Block::kDone, std::memory_order_release);
  }
  block_done_.notify_all();
}

void Lookahead::complete(Shot& shot, Block& block) {
  complete_or_wait(shot, block);
  const std::lock_guard<std::mutex> lock(mutex_);
  if (failure_) std::rethrow_exception(failure_);  // this block or another is unfinished
}

void Lookahead::complete_or_wait(Shot& shot, Block& block) {
  int expected = Block::kNotStarted;
  if (block.state.compare_exchange_strong(expected, Block::kStarted)) {
    compute(shot, block);
    finish(block);
    return;
  }
  // Being computed on another thread: help with the blocks nobody has started meanwhile.
  while (block.state.load(std::memory_order_acquire) != Block::kDone) {
    std::shared_ptr<Shot> other;
    Block* next = nullptr;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      next = claim_next(other);
      if (!next) {
        block_done_.wait(lock, [&] { return block.state.load(std::memory_order_acquire) == Block::kDone; });
        return;
      }
    }
    compute(*other, *next);
    finish(*next);
  }
}

bool Lookahead::answers(const OccluderSet& set, const Shooter& shooter, const PointBlock& asked,
                        PartMask* masks, WorkCounts& counts) {
  const std::size_t count = asked.count;
  const auto share = std::find(sets_.begin(), sets_.end(), &set);
  if (share == sets_.end() || count == 0) return false;
  std::shared_ptr<Shot> shot;
  Block* found = nullptr;
  // The same question (question_key.h): the shooter's and the block's bits.
  const auto is_asked = [&](const Shot& s, const Block& b) {
    return b.count == count && s.key_.is(shooter) &&
           same_block(PointBlock(s.points_, s.patches_).part(b.first, b.first + b.count), asked);
  };
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    // The V shares ask about the same block one after the other: the last one first.
    if (std::shared_ptr<Shot> s = last_found_.shot.lock(); s && is_asked(*s, *last_found_.block)) {
      shot = std::move(s);
      found = last_found_.block;
    }
    if (!found) {
      auto [begin, end] = posted_.equal_range(question_hash(asked));
      for (auto it = begin; it != end && !found; ++it) {
        std::shared_ptr<Shot> s = it->second.shot.lock();
        if (!s || !is_asked(*s, *it->second.block)) continue;
        shot = std::move(s);
        found = it->second.block;
        last_found_ = it->second;
      }
    }
  }
  if (!found) return false;
  complete(*shot, *found);
  const std::size_t s = std::size_t(share - sets_.begin());
  std::copy_n(found->answers.data() + s * count, count, masks);
  counts += found->counts[s];
  return true;
}

const double* Lookahead::form_factors(Shot& shot, int block, const PartMask* visible,
                                      std::size_t count) {
  if (block < 0 || std::size_t(block) >= shot.blocks_.size()) return nullptr;
  Block& b = *shot.blocks_[std::size_t(block)];
  complete(shot, b);
  if (b.count != count || !std::equal(visible, visible + count, b.visible.begin())) return nullptr;
  return b.form_factors.data();
}

std::shared_ptr<HostAssist::PostedShot> Lookahead::blocks_to_send(const Shooter& shooter,
                                                                  const std::vector<Vec3>& points,
                                                                  const std::vector<int>& patches,
                                                                  int block_size) {
  return post(shooter, points, patches, block_size);
}

const double* Lookahead::form_factors(PostedShot& shot, int block, const PartMask* visible,
                                      std::size_t count) {
  return form_factors(static_cast<Shot&>(shot), block, visible, count);
}

void Lookahead::engine_started(int rank, const RadiosityEngine& engine) {
  // Every element of the engine is a receiver of every shooter but its own patch's.
  std::vector<ElementRef> all;
  const auto& patches = engine.store().patches();
  for (int slot = 0; slot < int(patches.size()); ++slot)
    for (int k = 0; k < int(patches[std::size_t(slot)].elements.size()); ++k) all.push_back({slot, k});
  std::vector<Vec3> points;
  std::vector<int> point_patches;
  engine.visibility_points(all, points, point_patches);
  know_receivers(rank, std::move(points), std::move(point_patches));
}

void Lookahead::shot_finished(const RadiosityEngine& engine) {
  std::vector<std::pair<int, double>> powers;
  for (const StoredPatch& s : engine.store().patches()) {
    const Rgb& u = s.unshot;
    powers.emplace_back(s.patch, (u.r + u.g + u.b) * scene_.patches[std::size_t(s.patch)].area);
  }
  know_unshot(powers);
}

}  // namespace ncube

// Host threads computing ahead (host-side only; docs/performance.md, "Computing ahead").
//
// SimGrid runs every node program on one host thread, so a run with visibility processors
// (section 3) would use one core while the node programs wait for each other. But a shot's
// work is known as soon as a radiosity processor has its visibility points: the V shares'
// answers for each block of points (and their counts), and the form factors of the block
// once the answers are in. A radiosity processor posts its blocks here before it sends
// them; worker threads compute them in the order they will be asked for, while the main
// thread goes on simulating. A visibility processor asked about a posted block takes its
// share's answers from here; the radiosity processor takes the block's form factors. A
// block nobody has started yet is computed by the thread that needs it; one being computed
// is waited for (helping with the others meanwhile).
//
// Guesses: while no posted block is waiting (SimGrid's own work between blocks, or a shot
// whose answers were remembered), the workers compute the first shot of the patch most
// likely to be shot next that was never shot: the never-shot patch with the most unshot
// power, for the receivers every radiosity processor holds, in the blocks it would post.
// Its answers go to the answer cache (answer_cache.h) for when the patch is shot; a wrong
// guess costs only host time that would have been idle.
//
// Contract (host side): nothing simulated depends on it. Every answer, count and form factor
// is the one the node program would compute itself (the same functions, the same inputs;
// tested bit for bit), and the simulated machine is charged for the counts whoever computed
// them. It reaches the simulated program only through HostAssist (radiosity/host_assist.h)
// and through the shares' batch calls (fast_occluders.h).
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <memory>
#include <mutex>
#include <thread>
#include <unordered_map>
#include <vector>

#include "counts/work_counts.h"
#include "host/fast_occluders.h"
#include "host/fast_octree.h"
#include "host/host_side.h"
#include "host/threaded_assist.h"
#include "scene/scene.h"
#include "visibility/shooter.h"

namespace ncube {

class Lookahead : public ThreadedAssist {
 public:
  // `shares`: the sets every block is asked about (the V visibility processors' shares, the
  // same for every group; not owned), brute force or octree. `workers` >= 1 host threads
  // besides the main one.
  Lookahead(const Scene& scene, std::vector<const FastOccluders*> shares, int workers);
  Lookahead(const Scene& scene, std::vector<const FastOctree*> shares, int workers);
  ~Lookahead() override;  // stops the workers (blocks still posted are dropped)
  Lookahead(const Lookahead&) = delete;
  Lookahead& operator=(const Lookahead&) = delete;

  class Shot;  // the blocks one radiosity processor posted for one shooter
  // Posts points[0 .. n) in blocks of `block_size` (the last one shorter), as a radiosity
  // processor sends them. Main thread only. The blocks stay known while the handle lives.
  std::shared_ptr<Shot> post(const Shooter& shooter, const std::vector<Vec3>& points,
                             const std::vector<int>& patches, int block_size);

  // When a posted block has exactly these points, patches and shooter (question_key.h) and
  // `set` is one of the shares: writes the set's answers to masks[0 .. count), adds its
  // counts and returns true (false: not posted; the caller computes it).
  bool answers(const OccluderSet& set, const Shooter& shooter, const PointBlock& block,
               PartMask* masks, WorkCounts& counts);

  // The receivers' form factors (receiver_form_factor) of block `block` of `shot`, when
  // `visible` (count masks) is the block's visibility (the AND of the shares' answers);
  // null otherwise.
  const double* form_factors(Shot& shot, int block, const PartMask* visible, std::size_t count);

  // HostAssist: the blocks are posted, their form factors taken from here, and the engines'
  // receivers and unshot power feed the guesses.
  std::shared_ptr<PostedShot> blocks_to_send(const Shooter& shooter, const std::vector<Vec3>& points,
                                             const std::vector<int>& patches,
                                             int block_size) override;
  const double* form_factors(PostedShot& shot, int block, const PartMask* visible,
                             std::size_t count) override;
  void engine_started(int rank, const RadiosityEngine& engine) override;
  void shot_finished(const RadiosityEngine& engine) override;

  int workers() const { return int(threads_.size()); }

  // Guesses (above; brute-force shares only: their answers are remembered in the answer
  // cache, the octree's are not) need every radiosity processor's receivers: all its
  // elements' centres and patches in store order (the receivers of a shot are those not on
  // the shooter). Only for runs whose elements never change (no subdivision, no balancing)
  // and whose receivers do not depend on the shooter (every element traces rays). Main thread.
  void guess_shots(int samples, int block_size, int ranks);
  void know_receivers(int rank, std::vector<Vec3> points, std::vector<int> patches);
  // The unshot power of some patches as it is now (after a shot).
  void know_unshot(const std::vector<std::pair<int, double>>& powers);

 private:
  struct Block;
  Lookahead(const Scene& scene, std::vector<const FastOccluders*> brute_force,
            std::vector<const FastOctree*> octrees, int workers);

  void work();                                             // a worker thread's loop
  Block* claim_next(std::shared_ptr<Shot>& shot);          // under mutex_: a block nobody has started
  void compute(Shot& shot, Block& block);                  // the block's answers and form factors
  // Every share's answers (answers[s * n + k]) and counts for n points, as its batch call.
  void answer_shares(const Shooter& shooter,
                     const std::vector<std::shared_ptr<const FastOccluders::TargetSides>>& sides,
                     const PointBlock& block, PartMask* answers, WorkCounts* counts) const;
  void finish(Block& block);                               // done: wake those waiting
  // Done when it returns; rethrows a worker's exception (failure_).
  void complete(Shot& shot, Block& block);
  void complete_or_wait(Shot& shot, Block& block);
  // Under mutex_: the next block of a guessed shot (false: no guess to work on).
  struct GuessBlock {
    std::shared_ptr<const Shooter> shooter;
    std::shared_ptr<const std::vector<std::shared_ptr<const FastOccluders::TargetSides>>> sides;
    std::vector<Vec3> points;
    std::vector<int> patches;
  };
  bool next_guess_block(GuessBlock& block);
  void compute_guess(const GuessBlock& block);

  std::size_t share_count() const { return sets_.size(); }

  const Scene& scene_;
  std::vector<const FastOccluders*> shares_;      // brute-force shares (or none)
  std::vector<const FastOctree*> octree_shares_;  // octree shares (or none)
  std::vector<const OccluderSet*> sets_;          // all of them: brute force, then octree
  // The form factors of blocks shot before (a repeated shot has the same) are kept in the
  // scene's answer cache under this id.
  std::shared_ptr<const SceneBlockers> blockers_;
  std::uint64_t form_factor_set_;
  std::mutex mutex_;
  std::condition_variable work_to_do_, block_done_;
  bool stopping_ = false;
  // The first exception a worker thread met (the host out of memory): its block is marked
  // done unfinished, and the node program that needs a block rethrows it (complete()).
  std::exception_ptr failure_;
  std::vector<std::shared_ptr<Shot>> active_;  // shots with blocks nobody has started, oldest first
  struct Posted {
    std::weak_ptr<Shot> shot;  // expired once nobody holds the shot
    Block* block;
  };
  std::unordered_multimap<std::uint64_t, Posted> posted_;  // by hash of points and patches
  Posted last_found_{{}, nullptr};
  // Guesses (under mutex_).
  bool guessing_ = false;
  int samples_ = 0, block_size_ = 1;
  std::vector<std::vector<Vec3>> rank_points_;
  std::vector<std::vector<int>> rank_patches_;
  std::vector<double> unshot_power_;  // per scene patch
  std::vector<char> posted_patch_, guessed_patch_;  // per scene patch: shot, guessed
  GuessBlock guess_;                   // the shot being guessed: its shooter and sides
  std::size_t guess_rank_ = 0, guess_first_ = 0;
  std::vector<std::thread> threads_;
};

class Lookahead::Shot : public HostAssist::PostedShot {
 private:
  friend class Lookahead;
  Shooter shooter_;
  ShooterKey key_;
  std::vector<Vec3> points_;
  std::vector<int> patches_;
  std::vector<std::shared_ptr<const FastOccluders::TargetSides>> sides_;  // per share
  std::vector<std::unique_ptr<Block>> blocks_;
  std::size_t next_unclaimed_ = 0;  // under owner_->mutex_
};

}  // namespace ncube

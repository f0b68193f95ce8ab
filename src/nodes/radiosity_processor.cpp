#include "nodes/radiosity_processor.h"

#include <algorithm>
#include <xbt/log.h>

// --log=ncube_radiosity.thresh:verbose shows every decision, :debug every shot.
XBT_LOG_NEW_DEFAULT_CATEGORY(ncube_radiosity, "the radiosity processors (sections 2.2 and 3)");

namespace ncube {

RadiosityProcessor::RadiosityProcessor(const ProgramSetup& setup, int rank, NodeRuntime& runtime,
                                       RadiosityEngine& engine, const Occluders* occluders)
    : setup_(setup),
      rank_(rank),
      runtime_(runtime),
      engine_(engine),
      occluders_(occluders),
      selection_(runtime, setup_.placement, rank) {}

void RadiosityProcessor::run() {
  runtime_.start();
  // Section 6: with octree visibility, a node that tests rays first builds its octree.
  if (occluders_) runtime_.compute(occluders_->build_work());
  for (;;) {
    // Every processor offers the patch with the most unshot radiosity; the master chooses
    // the globally best as shooter and sends it to all (section 2.2).
    WorkCounts search;
    const ShooterChoice local_best = engine_.best_shooter(search);
    runtime_.compute(search);
    const ShooterChoice global_best = selection_.reduce_to_master(local_best);
    const ShooterChoice decision = selection_.broadcast_from_master(
        selection_.is_master() ? decide(global_best) : ShooterChoice{});
    tell_visibility_processors(decision);
    if (decision.patch < 0) break;
    shoot(make_shooter(setup_.scene, decision.patch, decision.unshot, setup_.options.samples));
    // Only the owner holds the shooter's unshot radiosity; it has now been shot.
    if (std::binary_search(engine_.owned_patches().begin(), engine_.owned_patches().end(),
                           decision.patch))
      engine_.clear_unshot(decision.patch);
  }
  runtime_.finish();
}

ShooterChoice RadiosityProcessor::decide(const ShooterChoice& global_best) {
  if (!shooters_.empty()) iteration_ends_.push_back(runtime_.now());
  const ProgressiveOptions& o = setup_.options;
  largest_unshot_power_ = global_best.power;
  converged_ = has_converged(global_best, setup_.emitted_power, o.convergence_fraction);
  if (converged_ || (o.max_iterations >= 0 && int(shooters_.size()) >= o.max_iterations))
    return ShooterChoice{};  // stop
  shooters_.push_back(global_best.patch);
  XBT_VERB("iteration %zu: shooter patch %d, unshot power %g", shooters_.size(),
           global_best.patch, global_best.power);
  return global_best;
}

void RadiosityProcessor::tell_visibility_processors(const ShooterChoice& decision) {
  // The shooter's geometry reaches the visibility processors by message (section 3).
  for (int j = 0; j < setup_.placement.visibility_processors; ++j) {
    auto message = std::make_unique<Message>();
    message->kind = decision.patch < 0 ? MessageKind::kStop : MessageKind::kShooter;
    message->candidate = decision;
    runtime_.send(setup_.placement.visibility_node(rank_, j), std::move(message));
  }
}

void RadiosityProcessor::shoot(const Shooter& shooter) {
  XBT_DEBUG("rank %d shoots patch %d", rank_, shooter.patch);
  if (setup_.placement.visibility_processors > 0) {
    shoot_with_visibility_processors(shooter);
    return;
  }
  // Section 2.2: for each receiving element, trace a ray to every part of the shooter and
  // intersect it with all other patches; add the light of the visible parts.
  WorkCounts work;
  const std::vector<int> receivers = engine_.receivers(shooter, setup_.options.skip_facing_away, work);
  const int threads = setup_.options.host_threads;
  const std::vector<PartMask> visible =
      visible_parts(setup_.scene, *occluders_, receivers, shooter, work, threads);
  engine_.gather(shooter, receivers, visible, work, threads);
  runtime_.compute(work);
}

void RadiosityProcessor::shoot_with_visibility_processors(const Shooter& shooter) {
  // Section 3: the visibility points go in blocks to every visibility processor of this
  // group; each answers with one bit vector per point (bit set: that part of the shooter is
  // not blocked by its share of the patches); the AND of the V answers is the visibility.
  WorkCounts facing;
  const std::vector<int> receivers = engine_.receivers(shooter, setup_.options.skip_facing_away, facing);
  runtime_.compute(facing);
  const int V = setup_.placement.visibility_processors;
  const int B = setup_.block_size;
  const int blocks = int((receivers.size() + B - 1) / B);
  std::vector<PartMask> visible(receivers.size(), shooter.all_parts());
  std::vector<int> answers(std::size_t(blocks), 0);
  if (blocks > 0) send_block(receivers, 0);
  for (int block = 0; block < blocks; ++block) {
    if (setup_.pipelined && block + 1 < blocks) send_block(receivers, block + 1);
    while (answers[block] < V) {
      const std::unique_ptr<Message> answer = runtime_.receive({MessageKind::kAnswers});
      for (std::size_t k = 0; k < answer->masks.size(); ++k)
        visible[std::size_t(answer->block) * B + k] &= answer->masks[k];
      ++answers[answer->block];
    }
    const auto first = std::size_t(block) * B;
    const auto last = std::min(receivers.size(), first + B);
    const std::vector<int> part(receivers.begin() + first, receivers.begin() + last);
    const std::vector<PartMask> masks(visible.begin() + first, visible.begin() + last);
    WorkCounts work;
    engine_.gather(shooter, part, masks, work, setup_.options.host_threads);
    runtime_.compute(work);
    if (!setup_.pipelined && block + 1 < blocks) send_block(receivers, block + 1);
  }
}

void RadiosityProcessor::send_block(const std::vector<int>& receivers, int block) {
  const auto first = std::size_t(block) * setup_.block_size;
  const auto last = std::min(receivers.size(), first + setup_.block_size);
  for (int j = 0; j < setup_.placement.visibility_processors; ++j) {
    auto message = std::make_unique<Message>();
    message->kind = MessageKind::kPoints;
    message->block = block;
    for (std::size_t k = first; k < last; ++k) {
      const Element& element = setup_.scene.elements[receivers[k]];
      message->points.push_back(element.centre);
      message->point_patches.push_back(element.patch);
    }
    runtime_.send(setup_.placement.visibility_node(rank_, j), std::move(message));
  }
}

}  // namespace ncube

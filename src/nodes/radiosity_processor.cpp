#include "nodes/radiosity_processor.h"

#include <algorithm>
#include <limits>
#include <xbt/log.h>

#include "radiosity/form_factor_methods.h"

// --log=ncube_radiosity.thresh:verbose shows every decision, :debug every shot.
XBT_LOG_NEW_DEFAULT_CATEGORY(ncube_radiosity, "the radiosity processors (sections 2.2, 3, 4)");

namespace ncube {

RadiosityProcessor::RadiosityProcessor(const ProgramSetup& setup, int rank, NodeRuntime& runtime,
                                       RadiosityEngine& engine, const OccluderSet* occluders)
    : setup_(setup),
      rank_(rank),
      runtime_(runtime),
      engine_(engine),
      occluders_(occluders),
      selection_(runtime, setup_.placement, rank) {}

void RadiosityProcessor::run() {
  runtime_.start();
  // Section 6: with octree visibility, a node that tests rays first builds its octree.
  if (occluders_) runtime_.charge(occluders_->build_work());
  // A node that computes form factors first does its method's setup (the hemicube's table).
  if (occluders_) {
    const WorkCounts setup = form_factor_methods().at(setup_.options.form_factors).setup_work(setup_.options);
    if (!(setup == WorkCounts{})) runtime_.charge(setup);
  }
  for (int pass = 1;; ++pass) {
    runtime_.set_trace_context(pass, -1);
    // Every processor offers the patch with the most unshot radiosity (and, when loads can
    // change, its load); the master chooses the globally best as shooter, and the patches
    // to move, and sends its decision to all (sections 2.2, 4.2).
    WorkCounts search;
    const ShooterChoice local_best = engine_.best_shooter(search);
    runtime_.charge(search);
    std::vector<ProcessorLoad> loads;
    if (setup_.loads_change()) loads.push_back(load(local_best.patch));
    const ShooterChoice global_best = selection_.reduce_to_master(local_best, loads);
    const Decision decision = selection_.broadcast_from_master(
        selection_.is_master() ? decide(global_best, loads) : Decision{});
    runtime_.set_trace_context(pass, decision.shooter.patch);
    tell_visibility_processors(decision);
    if (decision.shooter.patch < 0) break;
    carry_out(decision.transfers, decision.shooter.patch);
    shoot(make_shooter(setup_.scene, decision.shooter.patch, decision.shooter.unshot,
                       setup_.options.samples));
    // Only the holder keeps the shooter's unshot radiosity; it has now been shot.
    engine_.finish_shot(decision.shooter.patch);
  }
  runtime_.finish();
}

ProcessorLoad RadiosityProcessor::load(int candidate) const {
  ProcessorLoad l{rank_, engine_.store().element_count(), runtime_.memory(), wanted_bytes_};
  // The smallest patches it could give (in bytes, in elements): not its candidate, which
  // may become the shooter.
  for (const StoredPatch& s : engine_.store().patches()) {
    if (s.patch == candidate) continue;
    const double bytes = patch_bytes(setup_.scene, s, runtime_.costs(), !holds_geometry_of_all_patches());
    const long elements = long(s.elements.size());
    if (l.smallest_patch_bytes == 0.0 || bytes < l.smallest_patch_bytes) l.smallest_patch_bytes = bytes;
    if (l.smallest_patch_elements == 0 || elements < l.smallest_patch_elements)
      l.smallest_patch_elements = elements;
  }
  return l;
}

Decision RadiosityProcessor::decide(const ShooterChoice& global_best,
                                    const std::vector<ProcessorLoad>& loads) {
  if (!shooters_.empty()) iteration_ends_.push_back(runtime_.now());
  std::vector<long> elements;
  for (const ProcessorLoad& l : loads) elements.push_back(l.elements);
  if (!elements.empty()) elements_.push_back(elements);
  const ProgressiveOptions& o = setup_.options;
  largest_unshot_power_ = global_best.power;
  // Sections 4.1, 4.2: a processor that could not make its cuts gets room elsewhere, or the
  // run ends out of memory.
  const double capacity =
      setup_.memory_cap ? runtime_.node_memory() : std::numeric_limits<double>::infinity();
  BalanceDecision balance = plan_transfers(loads, capacity, setup_.balancing);
  if (balance.out_of_memory_rank >= 0) {
    out_of_memory_ = {setup_.placement.radiosity_node(balance.out_of_memory_rank),
                      balance.out_of_memory_needed};
    Decision stop;
    stop.out_of_memory = true;
    return stop;
  }
  converged_ = has_converged(global_best, setup_.emitted_power, o.convergence_fraction);
  if (converged_ || (o.max_iterations >= 0 && int(shooters_.size()) >= o.max_iterations))
    return Decision{};  // stop
  shooters_.push_back(global_best.patch);
  XBT_VERB("iteration %zu: shooter patch %d, unshot power %g, %zu transfers", shooters_.size(),
           global_best.patch, global_best.power, balance.transfers.size());
  return Decision{global_best, std::move(balance.transfers), false};
}

void RadiosityProcessor::tell_visibility_processors(const Decision& decision) {
  // The shooter's geometry reaches the visibility processors by message (section 3).
  for (int j = 0; j < setup_.placement.visibility_processors; ++j) {
    auto message = std::make_unique<Message>();
    message->kind = decision.shooter.patch < 0 ? MessageKind::kStop : MessageKind::kShooter;
    message->candidate = decision.shooter;
    runtime_.send(setup_.placement.visibility_node(rank_, j), std::move(message));
  }
}

void RadiosityProcessor::carry_out(const std::vector<Transfer>& transfers, int shooter) {
  // Section 4.2: "we can transfer some patches and the associated elements to a less loaded
  // processor". The sender chooses which; the receiver waits for them before it shoots.
  const bool with_geometry = !holds_geometry_of_all_patches();
  for (const Transfer& t : transfers) {
    if (t.from == rank_) {
      auto message = std::make_unique<Message>();
      message->kind = MessageKind::kPatches;
      message->patch_geometry = with_geometry;
      for (int patch : patches_to_move(engine_.store(), t, shooter, runtime_.costs(), with_geometry)) {
        message->patches.push_back(engine_.store().remove(patch));
        message->patch_records.push_back(patch_records(setup_.scene, message->patches.back()));
      }
      // The patches leave this node's memory as they travel: their bytes as held.
      const double bytes = payload_bytes(*message, runtime_.costs());
      patches_sent_ += long(message->patches.size());
      ++transfers_sent_;
      transfer_bytes_sent_ += bytes;
      runtime_.change_memory(-bytes);
      XBT_DEBUG("rank %d gives %zu patches (%.0f bytes) to rank %d", rank_, message->patches.size(),
                bytes, t.to);
      runtime_.send(setup_.placement.radiosity_node(t.to), std::move(message));
    } else if (t.to == rank_) {
      std::unique_ptr<Message> message = runtime_.receive({MessageKind::kPatches});
      for (StoredPatch& patch : message->patches) {
        runtime_.change_memory(patch_bytes(setup_.scene, patch, runtime_.costs(), with_geometry));
        engine_.store().insert(std::move(patch));
        ++patches_received_;
      }
    }
  }
}

void RadiosityProcessor::shoot(const Shooter& shooter) {
  XBT_DEBUG("rank %d shoots patch %d", rank_, shooter.patch);
  // Section 2.2: for each receiving element, find the visible parts of the shooter and add
  // the light through their form factors.
  WorkCounts facing;
  std::vector<ElementRef> receivers =
      engine_.receivers(shooter, setup_.options.skip_facing_away, facing);
  runtime_.charge(facing);
  wanted_bytes_ = 0.0;
  while (!receivers.empty()) {
    find_visible_parts_and_gather(shooter, receivers);
    if (!setup_.options.subdivision.enabled) break;
    // Section 4.1: "The test is done after the energy has been distributed to all
    // elements"; elements whose corners differ too much are cut, and the children receive
    // the current shot at their own centres, recursively.
    receivers = subdivide(receivers);
  }
}

std::vector<ElementRef> RadiosityProcessor::subdivide(const std::vector<ElementRef>& receivers) {
  // Each cut costs 4 element records of the node's memory.
  const double element_bytes = runtime_.costs().element_bytes;
  const long room = setup_.memory_cap ? runtime_.records_that_fit(element_bytes) : long(1) << 62;
  bool out_of_room = false;
  WorkCounts cutting;
  std::vector<ElementRef> children =
      engine_.subdivide(receivers, setup_.options.subdivision, room, out_of_room, cutting);
  runtime_.charge(cutting);
  runtime_.change_memory(double(children.size()) * element_bytes);
  if (out_of_room) wanted_bytes_ = 4.0 * element_bytes;  // at least one more cut
  return children;
}

void RadiosityProcessor::find_visible_parts_and_gather(const Shooter& shooter,
                                                       const std::vector<ElementRef>& receivers) {
  if (setup_.placement.visibility_processors > 0) {
    gather_with_visibility_processors(shooter, receivers);
    return;
  }
  // Section 2.2: trace a ray from each receiver to every part of the shooter and intersect
  // it with all other patches (or the run's other form-factor method over the same patches).
  WorkCounts work;
  form_factor_methods().at(setup_.options.form_factors)
      .shoot(engine_, *occluders_, shooter, receivers, setup_.options, work);
  runtime_.charge(work);
}

void RadiosityProcessor::gather_with_visibility_processors(const Shooter& shooter,
                                                           const std::vector<ElementRef>& receivers) {
  // Section 3: the visibility points go in blocks to every visibility processor of this
  // group; each answers with one bit vector per point (bit set: that part of the shooter is
  // not blocked by its share of the patches); the AND of the V answers is the visibility.
  const PointBlocks blocks = engine_.point_blocks(shooter, receivers, setup_.block_size);
  const int V = setup_.placement.visibility_processors;
  std::vector<PartMask> visible(receivers.size(), shooter.all_parts());
  std::vector<int> answers(std::size_t(blocks.count()), 0);
  if (blocks.count() > 0) send_block(blocks, 0);
  for (int block = 0; block < blocks.count(); ++block) {
    if (setup_.pipelined && block + 1 < blocks.count()) send_block(blocks, block + 1);
    while (answers[block] < V) {
      const std::unique_ptr<Message> answer = runtime_.receive({MessageKind::kAnswers});
      for (std::size_t k = 0; k < answer->masks.size(); ++k)
        visible[blocks.first(answer->block) + k] &= answer->masks[k];
      ++answers[answer->block];
    }
    const std::vector<PartMask> masks(visible.begin() + std::ptrdiff_t(blocks.first(block)),
                                      visible.begin() + std::ptrdiff_t(blocks.end(block)));
    WorkCounts work;
    form_factor_methods().at(setup_.options.form_factors)
        .gather_visible(engine_, shooter, receivers, blocks, block, masks, work);
    runtime_.charge(work);
    if (!setup_.pipelined && block + 1 < blocks.count()) send_block(blocks, block + 1);
  }
}

void RadiosityProcessor::send_block(const PointBlocks& blocks, int block) {
  const PointBlock points = blocks.block(block);
  for (int j = 0; j < setup_.placement.visibility_processors; ++j) {
    auto message = std::make_unique<Message>();
    message->kind = MessageKind::kPoints;
    message->block = block;
    message->points.assign(points.points, points.points + points.count);
    message->point_patches.assign(points.patches, points.patches + points.count);
    runtime_.send(setup_.placement.visibility_node(rank_, j), std::move(message));
  }
}

}  // namespace ncube

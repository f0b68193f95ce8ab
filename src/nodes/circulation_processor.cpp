#include "nodes/circulation_processor.h"

#include <algorithm>

#include <xbt/log.h>

#include "nodes/shooter_processor.h"
#include "radiosity/form_factor_methods.h"

// --log=ncube_circulation.thresh:verbose shows every iteration's shooters.
XBT_LOG_NEW_DEFAULT_CATEGORY(ncube_circulation, "the circulation scheme's nodes");

namespace ncube {

std::vector<std::vector<std::size_t>> owned_element_blocks(const Scene& scene,
                                                           const std::vector<std::vector<int>>& owned) {
  std::vector<std::vector<std::size_t>> blocks;
  for (const std::vector<int>& patches : owned) {
    std::vector<std::size_t>& block = blocks.emplace_back();
    for (int p : patches) {
      const Patch& patch = scene.patches[std::size_t(p)];
      for (int k = 0; k < patch.element_count(); ++k)
        block.push_back(std::size_t(patch.first_element + k));
    }
  }
  return blocks;
}

CirculationProcessor::CirculationProcessor(const ProgramSetup& setup, int rank,
                                           const std::vector<std::vector<int>>& owned,
                                           NodeRuntime& runtime, RadiosityEngine& engine,
                                           const OccluderSet& occluders)
    : setup_(setup),
      rank_(rank),
      runtime_(runtime),
      engine_(engine),
      occluders_(occluders),
      owned_(owned[std::size_t(rank)]),
      ring_(runtime, setup.placement, rank, owned_element_blocks(setup.scene, owned)) {
  const std::vector<StoredPatch>& stored = engine_.store().patches();
  for (int p : owned_)
    for (std::size_t slot = 0; slot < stored.size(); ++slot)
      if (stored[slot].patch == p) owned_slots_.push_back(int(slot));
}

void CirculationProcessor::run() {
  runtime_.start();
  runtime_.charge(occluders_.build_work());  // section 6: an octree over the scene, if any
  const WorkCounts setup = form_factor_methods().at(setup_.options.form_factors).setup_work(setup_.options);
  if (!(setup == WorkCounts{})) runtime_.charge(setup);
  const ProgressiveOptions& o = setup_.options;
  const std::size_t elements = std::size_t(setup_.scene.element_total());
  for (int iteration = 0;; ++iteration) {
    runtime_.set_trace_context(iteration + 1, -1);
    // Synchronous: every node's best patch goes round the ring, and every node decides alike.
    WorkCounts search;
    const ShooterChoice mine = local_best(search);
    runtime_.charge(search);
    const std::vector<ShooterChoice> chosen = choose(ring_.gather(mine, iteration));
    if (iteration > 0) iteration_ends_.push_back(runtime_.now());
    const ShooterChoice best = chosen.empty() ? ShooterChoice{} : chosen.front();
    largest_unshot_power_ = best.power;
    converged_ = has_converged(best, setup_.emitted_power, o.convergence_fraction);
    if (converged_ || (o.max_iterations >= 0 && iteration >= o.max_iterations)) break;
    if (rank_ == 0)
      XBT_VERB("iteration %d: %zu shooters, the best patch %d (unshot power %g)", iteration + 1,
               chosen.size(), best.patch, best.power);
    // This node shoots its own candidate if it is among the chosen, to every element.
    std::vector<Rgb> increments(elements, Rgb(0.0));
    const bool shooting = std::any_of(chosen.begin(), chosen.end(),
                                      [&](const ShooterChoice& c) { return c.patch == mine.patch; });
    if (shooting) {
      runtime_.set_trace_context(iteration + 1, mine.patch);
      shoot_to_scene(setup_, engine_, occluders_, mine, increments, runtime_);
    }
    // The light distribution: the sums for this node's elements come round the ring.
    apply(chosen, ring_.reduce_scatter(increments, iteration));
    for (const ShooterChoice& c : chosen) shooters_.push_back(c.patch);
  }
  runtime_.finish();
}

ShooterChoice CirculationProcessor::local_best(WorkCounts& counts) const {
  ShooterChoice best;
  const std::vector<StoredPatch>& stored = engine_.store().patches();
  for (int slot : owned_slots_) {
    const StoredPatch& s = stored[std::size_t(slot)];
    const Rgb& u = s.unshot;
    const ShooterChoice candidate{s.patch, (u.r + u.g + u.b) * setup_.scene.patches[std::size_t(s.patch)].area, u};
    if (candidate.power > 0.0 && candidate.better_than(best)) best = candidate;
  }
  counts.shooter_candidates += owned_slots_.size();
  return best;
}

std::vector<ShooterChoice> CirculationProcessor::choose(std::vector<ShooterChoice> candidates) const {
  candidates.erase(std::remove_if(candidates.begin(), candidates.end(),
                                  [](const ShooterChoice& c) { return !(c.patch >= 0 && c.power > 0.0); }),
                   candidates.end());
  std::sort(candidates.begin(), candidates.end(),
            [](const ShooterChoice& a, const ShooterChoice& b) { return a.better_than(b); });
  const std::size_t wanted = std::size_t(ShooterProcessor::shooters_per_iteration(setup_));
  if (candidates.size() > wanted) candidates.resize(wanted);
  return candidates;
}

void CirculationProcessor::apply(const std::vector<ShooterChoice>& shot, const std::vector<Rgb>& block) {
  for (const ShooterChoice& c : shot)
    if (std::find(owned_.begin(), owned_.end(), c.patch) != owned_.end()) engine_.finish_shot(c.patch);
  WorkCounts work;
  std::size_t at = 0;
  std::vector<StoredPatch>& stored = engine_.store().patches();
  for (int slot : owned_slots_) {
    StoredPatch& s = stored[std::size_t(slot)];
    const Patch& patch = setup_.scene.patches[std::size_t(s.patch)];
    for (StoredElement& element : s.elements) {
      const Rgb& gained = block[at++];
      element.radiosity += gained;
      s.unshot += gained * (element.area / patch.area);
      ++work.increments_applied;
    }
  }
  runtime_.charge(work);
}

}  // namespace ncube

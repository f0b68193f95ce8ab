#include "nodes/shooter_processor.h"

#include <xbt/log.h>

#include "radiosity/form_factor_methods.h"

// --log=ncube_shooters.thresh:verbose shows every iteration's shooters.
XBT_LOG_NEW_DEFAULT_CATEGORY(ncube_shooters, "the shooter-centred scheme's nodes");

namespace ncube {

ShooterProcessor::ShooterProcessor(const ProgramSetup& setup, int rank, NodeRuntime& runtime,
                                   RadiosityEngine& engine, const OccluderSet& occluders)
    : setup_(setup),
      rank_(rank),
      runtime_(runtime),
      engine_(engine),
      occluders_(occluders),
      exchange_(runtime, setup_.placement, rank) {}

int ShooterProcessor::shooters_per_iteration(const ProgramSetup& setup) {
  return setup.shooters_per_iteration > 0 ? setup.shooters_per_iteration
                                          : setup.placement.radiosity_processors;
}

void ShooterProcessor::run() {
  runtime_.start();
  runtime_.charge(occluders_.build_work());  // section 6: an octree over the scene, if any
  // The form-factor method's setup once (the hemicube's delta form factor table; none for rays).
  const WorkCounts setup = form_factor_methods().at(setup_.options.form_factors).setup_work(setup_.options);
  if (!(setup == WorkCounts{})) runtime_.charge(setup);
  const ProgressiveOptions& o = setup_.options;
  const std::size_t elements = std::size_t(setup_.scene.element_total());
  for (int iteration = 0;; ++iteration) {
    runtime_.set_trace_context(iteration + 1, -1);
    // Every node holds every patch's unshot radiosity, so every node chooses the same
    // shooters without asking anyone.
    WorkCounts search;
    const std::vector<ShooterChoice> chosen = choose_shooters(search);
    runtime_.charge(search);
    if (iteration > 0) iteration_ends_.push_back(runtime_.now());
    const ShooterChoice best = chosen.empty() ? ShooterChoice{} : chosen.front();
    largest_unshot_power_ = best.power;
    // The paper's criterion on the best shooter (section 2.2), and --iterations counts
    // iterations of S shots each.
    converged_ = has_converged(best, setup_.emitted_power, o.convergence_fraction);
    if (converged_ || (o.max_iterations >= 0 && iteration >= o.max_iterations)) break;
    if (rank_ == 0)  // every node chooses the same
      XBT_VERB("iteration %d: %zu shooters, the best patch %d (unshot power %g)", iteration + 1,
               chosen.size(), best.patch, best.power);
    std::vector<Rgb> increments(elements, Rgb(0.0));
    if (std::size_t(rank_) < chosen.size())
      runtime_.set_trace_context(iteration + 1, chosen[std::size_t(rank_)].patch);
    if (std::size_t(rank_) < chosen.size())
      shoot_to_scene(setup_, engine_, occluders_, chosen[std::size_t(rank_)], increments, runtime_);
    exchange_.sum(increments, iteration);
    apply(chosen, increments);
    for (const ShooterChoice& c : chosen) shooters_.push_back(c.patch);
  }
  runtime_.finish();
}

std::vector<ShooterChoice> ShooterProcessor::choose_shooters(WorkCounts& counts) const {
  const std::size_t wanted = std::size_t(shooters_per_iteration(setup_));
  std::vector<ShooterChoice> best;  // sorted, best first
  for (const StoredPatch& s : engine_.store().patches()) {
    const Rgb& u = s.unshot;
    const ShooterChoice candidate{s.patch, (u.r + u.g + u.b) * setup_.scene.patches[std::size_t(s.patch)].area, u};
    if (!(candidate.power > 0.0)) continue;  // nothing to shoot
    if (best.size() == wanted && !candidate.better_than(best.back())) continue;
    auto at = best.begin();
    while (at != best.end() && !candidate.better_than(*at)) ++at;
    best.insert(at, candidate);
    if (best.size() > wanted) best.pop_back();
  }
  counts.shooter_candidates += engine_.store().patches().size();
  return best;
}

void shoot_to_scene(const ProgramSetup& setup, RadiosityEngine& engine, const OccluderSet& occluders,
                    const ShooterChoice& choice, std::vector<Rgb>& increments, NodeRuntime& runtime) {
  const Shooter shooter = make_shooter(setup.scene, choice.patch, choice.unshot, setup.options.samples);
  WorkCounts work;
  const std::vector<ElementRef> receivers =
      engine.receivers(shooter, setup.options.skip_facing_away, work);
  // The form-factor step: the shooter's form factor to every receiving element, by the
  // run's method over the whole scene (the hemicube draws every other patch's elements as
  // occluders, as the paper's program at R = 1 does).
  const std::vector<double> form_factors = form_factor_methods().at(setup.options.form_factors)
      .form_factors(engine, occluders, shooter, receivers, setup.options, work);
  const std::vector<StoredPatch>& patches = engine.store().patches();
  for (std::size_t k = 0; k < receivers.size(); ++k) {
    const Patch& patch = setup.scene.patches[std::size_t(patches[std::size_t(receivers[k].slot)].patch)];
    // Reciprocity, as the paper's gather (RadiosityEngine::add_light): rho_e F(e -> s) unshot.
    increments[std::size_t(patch.first_element + receivers[k].index)] =
        patch.reflectance * shooter.unshot * form_factors[k];
    ++work.element_updates;
  }
  runtime.charge(work);
}

void ShooterProcessor::apply(const std::vector<ShooterChoice>& shot,
                             const std::vector<Rgb>& increments) {
  for (const ShooterChoice& c : shot) engine_.finish_shot(c.patch);
  WorkCounts work;
  for (StoredPatch& s : engine_.store().patches()) {
    const Patch& patch = setup_.scene.patches[std::size_t(s.patch)];
    for (std::size_t k = 0; k < s.elements.size(); ++k) {
      StoredElement& element = s.elements[k];
      const Rgb& gained = increments[std::size_t(patch.first_element) + k];
      element.radiosity += gained;
      s.unshot += gained * (element.area / patch.area);
      ++work.increments_applied;
    }
  }
  runtime_.charge(work);
}

}  // namespace ncube

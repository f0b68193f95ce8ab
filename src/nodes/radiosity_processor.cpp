#include "nodes/radiosity_processor.h"

namespace ncube {

RadiosityProcessor::RadiosityProcessor(NodeRuntime& runtime, RadiosityEngine& engine,
                                       const Occluders& occluders,
                                       const ProgressiveOptions& options)
    : runtime_(runtime),
      engine_(engine),
      occluders_(occluders),
      options_(options),
      emitted_power_(engine.scene().emitted_power()) {}

void RadiosityProcessor::run() {
  for (;;) {
    const double start = runtime_.now();
    // The patch with the most unshot radiosity becomes the shooter.
    WorkCounts search;
    const ShooterChoice best = engine_.best_shooter(search);
    runtime_.compute(search);
    if (has_converged(best, emitted_power_, options_.convergence_fraction)) {
      converged_ = true;
      return;
    }
    if (options_.max_iterations >= 0 && int(iterations_.size()) >= options_.max_iterations) return;
    shoot(make_shooter(engine_.scene(), best.patch, best.unshot, options_.samples));
    engine_.clear_unshot(best.patch);
    iterations_.push_back({best.patch, start, runtime_.now()});
  }
}

void RadiosityProcessor::shoot(const Shooter& shooter) {
  // For each receiving element: trace a ray to every part of the shooter, intersecting it
  // with all other patches; then the form factor of the visible parts (section 2.2).
  WorkCounts work;
  const std::vector<int> receivers = engine_.receivers(shooter, work);
  std::vector<PartMask> visible(receivers.size());
  for (std::size_t k = 0; k < receivers.size(); ++k) {
    const Element& element = engine_.scene().elements[receivers[k]];
    visible[k] = occluders_.unblocked_parts(element.centre, element.patch, shooter, work);
  }
  engine_.gather(shooter, receivers, visible, work);
  runtime_.compute(work);
}

}  // namespace ncube

// Two form-factor methods registered from outside the simulator's own list, built only into
// build/simulate_throwaway (never into ./simulate) for tests/throwaway_methods_test.sh: a
// method is one registration (docs/architecture.md, "How to add a method"), so every consumer
// (the option and --describe-options, the configuration check, the result file, the run's
// summary, the counters written, the V > 0 gather and the sweep's rules) must know these two
// without an edit of its own.
#include <string>
#include <utility>
#include <vector>

#include "radiosity/form_factor.h"
#include "radiosity/form_factor_methods.h"
#include "simulation/host_machinery.h"

namespace ncube {
namespace {

// test-halved: the paper's ray-traced form factors, halved. Defined with visibility processors
// through its own gather, so a V > 0 run whose light is not halved shows a gather that did not
// call the method's own.
std::vector<double> halved(std::vector<double> form_factors) {
  for (double& f : form_factors) f *= 0.5;
  return form_factors;
}

FormFactorMethod test_halved() {
  FormFactorMethod m;
  m.name = "test-halved";
  m.doc = "a test's method: the ray-traced form factors, halved";
  m.form_factors = [](RadiosityEngine& engine, const OccluderSet& occluders, const Shooter& shooter,
                      const std::vector<ElementRef>& receivers, const ProgressiveOptions&,
                      WorkCounts& counts) {
    return halved(ray_traced_form_factors(engine, occluders, receivers, shooter, counts));
  };
  m.shoot = [form_factors = m.form_factors](RadiosityEngine& engine, const OccluderSet& occluders,
                                            const Shooter& shooter,
                                            const std::vector<ElementRef>& receivers,
                                            const ProgressiveOptions& options, WorkCounts& counts) {
    engine.gather_form_factors(shooter, receivers,
                               form_factors(engine, occluders, shooter, receivers, options, counts),
                               counts);
  };
  m.gather_visible = [](RadiosityEngine& engine, const Shooter& shooter,
                        const std::vector<ElementRef>& receivers, const PointBlocks& blocks,
                        int block, const std::vector<PartMask>& masks, WorkCounts& counts) {
    const std::vector<ElementRef> part(receivers.begin() + std::ptrdiff_t(blocks.first(block)),
                                       receivers.begin() + std::ptrdiff_t(blocks.end(block)));
    engine.gather_form_factors(shooter, part, halved(engine.form_factors(shooter, part, masks)),
                               counts);
  };
  m.setup_work = [](const ProgressiveOptions&) { return WorkCounts{}; };
  m.node_items = [](const ProgressiveOptions&) { return HeldItems{}; };
  m.setting = [](const ProgressiveOptions& options) {
    return std::to_string(options.samples) + " samples per shooter, halved";
  };
  m.counted = [](const WorkCounts& counts) {
    return std::make_pair(std::string("rays"), std::to_string(counts.rays) + " traced");
  };
  return m;
}

// test-unoccluded: every part of the shooter seen from every receiver, no ray traced; V = 0
// only, and the rays' options refused.
FormFactorMethod test_unoccluded() {
  FormFactorMethod m;
  m.name = "test-unoccluded";
  m.doc = "a test's method: no occlusion, no rays";
  m.form_factors = [](RadiosityEngine& engine, const OccluderSet&, const Shooter& shooter,
                      const std::vector<ElementRef>& receivers, const ProgressiveOptions&,
                      WorkCounts&) {
    return engine.form_factors(shooter, receivers,
                               std::vector<PartMask>(receivers.size(), shooter.all_parts()));
  };
  m.shoot = [form_factors = m.form_factors](RadiosityEngine& engine, const OccluderSet& occluders,
                                            const Shooter& shooter,
                                            const std::vector<ElementRef>& receivers,
                                            const ProgressiveOptions& options, WorkCounts& counts) {
    engine.gather_form_factors(shooter, receivers,
                               form_factors(engine, occluders, shooter, receivers, options, counts),
                               counts);
  };
  m.without_visibility_processors = "the test's unoccluded method asks no visibility processor";
  m.traces_rays = false;
  m.setup_work = [](const ProgressiveOptions&) { return WorkCounts{}; };
  m.node_items = [](const ProgressiveOptions&) { return HeldItems{}; };
  m.setting = [](const ProgressiveOptions&) { return std::string("unoccluded"); };
  m.counted = [](const WorkCounts& counts) {
    return std::make_pair(std::string("element updates"), std::to_string(counts.element_updates));
  };
  return m;
}

const bool registered = [] {
  add_form_factor_method(test_halved());
  add_form_factor_method(test_unoccluded());
  add_host_form_factor_method("test-halved", "the readable definition");
  add_host_form_factor_method("test-unoccluded", "the readable definition");
  return true;
}();

}  // namespace
}  // namespace ncube

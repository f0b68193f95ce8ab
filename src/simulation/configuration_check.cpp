#include "simulation/configuration_check.h"

#include <string>

#include "radiosity/form_factor_methods.h"
#include "simulation/parallelisations.h"
#include "simulation/render_phase.h"
#include "util/input_error.h"
#include "visibility/shooter.h"

namespace ncube {

namespace {

// The form-factor method and the options that go with it (a method's options without it, or
// options it cannot honour, are refused rather than silently ignored).
void check_form_factor_options(const SimulationConfig& config) {
  const ProgressiveOptions& o = config.options;
  const FormFactorMethod& method = form_factor_methods().at(o.form_factors);
  const std::string named = "--form-factors " + method.name;
  if (config.visibility_processors > 0 && !method.gather_visible)
    throw InputError(named + " with --V " + std::to_string(config.visibility_processors) +
                     ": not defined with visibility processors (V = 0 only): " +
                     method.without_visibility_processors);
  if (method.refused_options) {
    const std::string refused = method.refused_options(o);
    if (!refused.empty()) throw InputError(refused);
  }
  const ProgressiveOptions defaults;
  if (!method.traces_rays) {
    // No rays are traced: the options of the rays would have no effect.
    const std::string none = ": the " + method.name + " traces no rays";
    if (o.visibility != defaults.visibility)
      throw InputError(named + " with --visibility " + o.visibility + none +
                       " (leave --visibility at " + defaults.visibility + ")");
    if (o.ray_policy != defaults.ray_policy)
      throw InputError(named + " with --ray-test first-blocker" + none);
    if (o.samples != defaults.samples)
      throw InputError(named + " with --samples " + std::to_string(o.samples) + ": the " +
                       method.name + " does not cut the shooter into parts (leave --samples at " +
                       std::to_string(defaults.samples) + ")");
  }
  // Another method's own options would have no effect.
  for (const FormFactorMethod& other : form_factor_methods().all())
    if (other.name != method.name && other.changed_options)
      for (const std::string& changed : other.changed_options(o))
        throw InputError(changed + " without --form-factors " + other.name +
                         ": it would have no effect");
}

}  // namespace

void check_configuration(const Scene& scene, const SimulationConfig& config,
                         const PlatformConfig& platform) {
  const int r = config.radiosity_processors, v = config.visibility_processors;
  const std::string rv = "R=" + std::to_string(r) + ", V=" + std::to_string(v);
  if (r < 1) throw InputError("--R " + std::to_string(r) + ": at least one radiosity processor is needed");
  if (v < 0) throw InputError("--V " + std::to_string(v) + ": must be 0 or more");
  // In 64 bits: R and V are up to 2^31 - 1 each.
  if (long(r) * (long(v) + 1) > platform.node_count())
    throw InputError(rv + " needs R x (V + 1) = " + std::to_string(long(r) * (long(v) + 1)) +
                     " nodes; the platform has " + std::to_string(platform.node_count()));
  if (r > int(scene.patches.size()))
    throw InputError(rv + ": more radiosity processors than the scene's " +
                     std::to_string(scene.patches.size()) + " patches");
  if (!is_valid_part_count(config.options.samples))
    throw InputError("--samples " + std::to_string(config.options.samples) +
                     ": must be a perfect square from 1 to 64 (e.g. 16 or 64)");
  check_form_factor_options(config);
  if (config.block_size < 1)
    throw InputError("--block-size " + std::to_string(config.block_size) + ": must be at least 1");
  check_render_configuration(config.render, config.node_count());
  parallelisations().at(config.parallelisation).check(scene, config);
}

}  // namespace ncube

#include "simulation/configuration_check.h"

#include <string>

#include "radiosity/shooter.h"
#include "simulation/parallelisations.h"
#include "simulation/render_phase.h"
#include "util/input_error.h"

namespace ncube {

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
  if (config.block_size < 1)
    throw InputError("--block-size " + std::to_string(config.block_size) + ": must be at least 1");
  check_render_configuration(config.render, config.node_count());
  parallelisations().at(config.parallelisation).check(scene, config);
}

}  // namespace ncube

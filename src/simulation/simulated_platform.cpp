#include "simulation/simulated_platform.h"

#include "machine/hypercube.h"
#include "machine/simgrid_platform_file.h"
#include "machine/simgrid_session.h"

namespace ncube {

std::vector<simgrid::s4u::Host*> build_simulated_platform(
    const PlatformConfig& platform, const std::vector<std::string>& simgrid_arguments) {
  simgrid_engine(simgrid_arguments);
  if (platform.format == "simgrid-xml")
    return simgrid_platform_nodes(platform);  // loaded with its <config> by the reader
  apply_simgrid_defaults(platform.simgrid_config);  // before the first zone
  return build_hypercube(platform);
}

}  // namespace ncube

// The simulated machine of a run: SimGrid's Engine (with its command-line settings) and the
// nodes' hosts, from a platforms/ description (the hypercube built here, or a SimGrid XML
// file's).
#pragma once

#include <string>
#include <vector>

#include <simgrid/s4u/Host.hpp>

#include "machine/platform_config.h"

namespace ncube {

// The platform's hosts in node order. Creates the Engine first (with `simgrid_arguments`);
// a hypercube platform's SimGrid defaults are applied before its first zone.
std::vector<simgrid::s4u::Host*> build_simulated_platform(
    const PlatformConfig& platform, const std::vector<std::string>& simgrid_arguments);

}  // namespace ncube

// The one SimGrid Engine of a process (SimGrid allows one), created with SimGrid's own
// command-line arguments (--cfg=name:value, --log=...), and the SimGrid settings a platform
// asks for, as defaults that --cfg overrides (docs/cli.md, "SimGrid's conventions").
#pragma once

#include <map>
#include <string>
#include <vector>

#include <simgrid/s4u/Engine.hpp>

namespace ncube {

// Creates the Engine on the first call (later calls return it; their arguments are ignored).
// The project's log default (warnings only) is set first, so that --log= can lower it.
simgrid::s4u::Engine& simgrid_engine(const std::vector<std::string>& arguments);

// Sets each setting that the command line did not set (a platform's defaults).
void apply_simgrid_defaults(const std::map<std::string, std::string>& settings);

// The settings in force: the network model's (read back from SimGrid) and every --cfg name.
std::map<std::string, std::string> simgrid_settings_used(const std::vector<std::string>& arguments);

}  // namespace ncube

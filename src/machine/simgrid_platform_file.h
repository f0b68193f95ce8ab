// A SimGrid platform file (XML) as the machine: any interconnect SimGrid can describe (a 2D
// mesh, a fat tree, ...) runs the same node programs (docs/platforms.md). Node k is the host
// "node-k" (k = 0 ... n-1); its speed is the host's; the machine parameters SimGrid has no
// notion of (XmlForm::kProperty in src/machine/machine_parameters.h: node_memory,
// send_overhead, receive_overhead) are host properties or properties of the host's zone. The
// file's <config> tags are defaults that --cfg overrides.
#pragma once

#include <string>
#include <vector>

#include <simgrid/s4u/Host.hpp>

#include "machine/platform_config.h"

namespace ncube {

// Whether `path` is XML (its first non-blank character is '<').
bool is_simgrid_platform_file(const std::string& path);

// What ./simulate holds a platform file's text to before SimGrid reads it: its shape (depth,
// hosts: platform_shape.h), no document type of its own (an internal DTD subset or an entity),
// every <config> setting within its range and none naming a file, no attribute naming a file.
// Throws InputError naming the file and the item. A tool that copies a platform file into one
// it writes (build/machine_probe) holds it to the same.
void check_simgrid_platform_text(const std::string& path, const std::string& text);

// Loads the platform into the process's SimGrid Engine (created with `simgrid_arguments`) and
// reads the nodes. Throws InputError naming the file, the host and the property (or the
// speed) that is missing, out of the parameter's range, or not node-0's.
PlatformConfig read_simgrid_platform_file(const std::string& path,
                                          const std::vector<std::string>& simgrid_arguments);

// The loaded platform's nodes in node order.
std::vector<simgrid::s4u::Host*> simgrid_platform_nodes(const PlatformConfig& platform);

}  // namespace ncube

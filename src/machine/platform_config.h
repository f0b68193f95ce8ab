// The modeled machine, read from platforms/<machine>.json (e.g. platforms/ncube2.json).
// The machine's values live in that file only (one source): a default-constructed
// PlatformConfig has every number 0, never the nCube2's; its only defaults are the format and
// the SimGrid settings a JSON file without "simgrid_config" gets (below).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "machine/machine_parameters.h"

namespace ncube {

struct PlatformConfig {
  // One field per machine parameter (src/machine/machine_parameters.h: unit, range, meaning).
#define NCUBE_PLATFORM_FIELD(name, type, unit, low, high, whole, xml, optional, doc) type name = 0;
  NCUBE_MACHINE_PARAMETERS(NCUBE_PLATFORM_FIELD)
#undef NCUBE_PLATFORM_FIELD

  // "json" (this project's parameter file, the hypercube built in code) or "simgrid-xml" (a
  // SimGrid platform file, any interconnect: docs/platforms.md).
  std::string format = "json";
  // SimGrid settings the platform asks for, defaults that --cfg overrides. Without a
  // "simgrid_config" in the file, the nCube2's network model (NCUBE_NETWORK_MODEL).
  std::map<std::string, std::string> simgrid_config = default_network_model();
  int xml_nodes = 0;  // "simgrid-xml": hosts node-0 ... node-(n-1)

  int node_count() const { return format == "json" ? 1 << dimension : xml_nodes; }
};

// Reads a JSON parameter file or a SimGrid platform file (XML, recognised by its first
// character; loading it creates the process's SimGrid Engine with `simgrid_arguments`).
PlatformConfig load_platform_config(const std::string& path,
                                    const std::vector<std::string>& simgrid_arguments = {});

}  // namespace ncube

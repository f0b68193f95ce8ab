// The modeled machine, read from platforms/<machine>.json (e.g. platforms/ncube2.json).
// The machine's values live in that file only (one source): a default-constructed
// PlatformConfig has every number 0, never the nCube2's; its only defaults are the format and
// the SimGrid settings a JSON file without "simgrid_config" gets (below).
#pragma once

#include <map>
#include <string>
#include <vector>

namespace ncube {

struct PlatformConfig {
  int dimension = 0;              // hypercube dimension: 2^dimension nodes
  double node_speed = 0.0;        // flop/s of one node
  double node_memory = 0.0;       // bytes of one node
  double link_bandwidth = 0.0;    // bytes/s per direction of one link
  double hop_latency = 0.0;       // s per hop of a route
  double send_overhead = 0.0;     // CPU s of the sender per message
  double receive_overhead = 0.0;  // CPU s of the receiver per message

  // "json" (this project's parameter file, the hypercube built in code) or "simgrid-xml" (a
  // SimGrid platform file, any interconnect: docs/platforms.md).
  std::string format = "json";
  // SimGrid settings the platform asks for, defaults that --cfg overrides. Without a
  // "simgrid_config" in the file, the nCube2's network model (docs/model.md): CM02 has no
  // latency or bandwidth correction factors (SimGrid's default LV08 multiplies latency by 13),
  // without cross traffic there is no reverse acknowledgement flow, and the fair-bottleneck
  // solver shares a link equally between the messages crossing it.
  std::map<std::string, std::string> simgrid_config = {{"network/model", "CM02"},
                                                       {"network/crosstraffic", "0"},
                                                       {"network/solver", "fairbottleneck"}};
  int xml_nodes = 0;  // "simgrid-xml": hosts node-0 ... node-(n-1)

  int node_count() const { return format == "json" ? 1 << dimension : xml_nodes; }
};

// Reads a JSON parameter file or a SimGrid platform file (XML, recognised by its first
// character; loading it creates the process's SimGrid Engine with `simgrid_arguments`).
PlatformConfig load_platform_config(const std::string& path,
                                    const std::vector<std::string>& simgrid_arguments = {});

}  // namespace ncube

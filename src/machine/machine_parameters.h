// The one list of machine parameters: every number a platform file gives the simulator, with
// its unit, the range the loaders accept, what it is and which platform forms carry it.
// PlatformConfig's fields are declared from it, and the JSON loader, the SimGrid XML reader
// and its per-node check, the result file's provenance, the tables of docs/model.md,
// docs/platforms.md and docs/result-format.md (docs/platform_tables.py reads this header) and
// the robustness suite's bounds (tests/robustness/cases.py) all iterate it. Adding a
// parameter: docs/architecture.md, "How to add a machine parameter".
#pragma once

#include <map>
#include <string>
#include <vector>

#include "machine/parameter_file.h"

namespace ncube {

struct PlatformConfig;

// How a SimGrid platform file (XML, docs/platforms.md) gives a parameter.
enum class XmlForm {
  kInterconnect,  // no value: the file's own links and routes are the interconnect
  kHostSpeed,     // the speed attribute of every node host (flop/s)
  kProperty,      // a <prop> of every node host, or of the host's zone (a <cluster>'s <prop>)
};

// X(name, C++ type, unit, smallest, largest, whole number, XmlForm, optional, what it is)
// One entry a line group, in the order the result file's values were first written. The
// ranges are sanity bounds far around the nCube2's values (a choice: beyond them a value is a
// typo, and simulated times could leave the range SimGrid computes in). A platform file's
// "unit", when it gives one, must be the unit here. An optional parameter (the rates per kind
// of work) may be left out of a platform file: it is then 0 in PlatformConfig, the kind of
// work runs at node_speed (ray_speed's at test_speed: NCUBE_RATE_FALLBACKS in
// src/machine/work_kinds.h), and the result file's provenance does not list it (so a machine
// that gives only node_speed has the results, and the result files, it had before the rates
// existed). docs/platform_tables.py parses these entries: keep each field a plain literal.
#define NCUBE_MACHINE_PARAMETERS(X)                                                             \
  X(dimension, int, "", 0, 13, true, kInterconnect, false,                                      \
    "hypercube dimension: the machine has 2^dimension nodes, node k's bit i is its "            \
    "coordinate in dimension i (the simulator builds the hypercube with e-cube routing)")       \
  X(node_speed, double, "flop/s", 1e3, 1e15, false, kHostSpeed, false,                          \
    "floating-point speed of one node, the rate at which counted work (cost_model.json) is "    \
    "executed; every node has the same")                                                        \
  X(node_memory, double, "byte", 1, 0x1p50, true, kProperty, false,                             \
    "memory of one node; the node programs account their modeled bytes against it")             \
  X(link_bandwidth, double, "byte/s", 1e3, 1e15, false, kInterconnect, false,                   \
    "bandwidth of one hypercube link in each direction (links are full duplex)")                \
  X(hop_latency, double, "s", 0, 1, false, kInterconnect, false,                                \
    "latency per hop of a route: a message alone over h hops takes h x hop_latency + "          \
    "bytes / link_bandwidth")                                                                   \
  X(send_overhead, double, "s", 0, 1, false, kProperty, false,                                  \
    "CPU time the sending node spends per message before it leaves")                            \
  X(receive_overhead, double, "s", 0, 1, false, kProperty, false,                               \
    "CPU time the receiving node spends per message when its program takes it")                 \
  X(test_speed, double, "flop/s", 1e3, 1e15, false, kProperty, true,                            \
    "speed of one node on floating-point tests: the compare-and-branch loops of the visibility " \
    "search (ray-patch tests and their plane crossings, octree slab tests, the shooter "       \
    "search, hemicube clip and depth tests, the renderer's sample tests; rays too when "        \
    "ray_speed is left out), flops of cost_model.json per second; left out: node_speed")       \
  X(arithmetic_speed, double, "flop/s", 1e3, 1e15, false, kProperty, true,                      \
    "speed of one node on straight-line floating-point arithmetic: form factors (arctangents, " \
    "square roots, divisions), radiosity updates, subdivision, hemicube transforms and "        \
    "projections, the renderer's vertices, triangles and pixels; left out: node_speed")         \
  X(memory_speed, double, "flop/s", 1e3, 1e15, false, kProperty, true,                          \
    "speed of one node on work that moves or accumulates data with one operation an item: "     \
    "radiosity increments combined and applied, hemicube cells read out, histogram buckets "    \
    "added; left out: node_speed")                                                              \
  X(ray_speed, double, "flop/s", 1e3, 1e15, false, kProperty, true,                             \
    "speed of one node on a ray's own work besides its tests (flops_per_ray of "                \
    "cost_model.json per second): setting the ray up, starting and leaving its loop over the "  \
    "patches, the patches it skips (its own and the shooter's); left out: test_speed, as "      \
    "before this rate existed (node_speed when that too is left out)")                        \
  X(blocked_ray_speed, double, "flop/s", 1e3, 1e15, false, kProperty, true,                     \
    "speed of one node on what a blocked ray costs beyond its counted tests (flops_per_blocked_ray " \
    "of cost_model.json per second): the edge tests of the patches that stop it and a branch "  \
    "the core could not foretell; left out: blocked rays are not charged (nor written), as "   \
    "before this rate existed")                                                                 \
  X(edge_term_speed, double, "flop/s", 1e3, 1e15, false, kProperty, true,                       \
    "speed of one node on the contour integrals' edge terms as the host sums them "            \
    "(flops_per_form_factor_edge_term of cost_model.json per second: cross product, norm, "     \
    "arctangent); left out: they are not charged (nor written), as before this rate existed") \
  X(projection_speed, double, "flop/s", 1e3, 1e15, false, kProperty, true,                      \
    "speed of one node on a polygon's way into a hemicube face: its vertices moved into the "   \
    "hemicube's frame, clipped to the face and projected, its plane and scan set up "          \
    "(flops_per_hemicube_vertex_transformed, _polygon_set_up, _clip_test, _clip_cut, "         \
    "_vertex_projected, _polygon_scanned per second); left out: each at the rate that ran it "  \
    "before this rate existed (arithmetic_speed, the clip tests test_speed)")                  \
  X(raster_speed, double, "flop/s", 1e3, 1e15, false, kProperty, true,                          \
    "speed of one node on a hemicube's scan conversion and item buffer: rows scanned, cells "   \
    "depth-tested, cells read out (flops_per_hemicube_row_scanned, _depth_test, _cell_read "    \
    "per second); left out: each at the rate that ran it before this rate existed "             \
    "(arithmetic_speed, test_speed, memory_speed)")

// The network model a JSON platform file gets when it has no "simgrid_config" (the nCube2's,
// docs/model.md): X(SimGrid setting, value, why). Defaults that --cfg overrides. The one
// place of these values: platforms/ncube2.json and platforms/ncube2.xml repeat them only
// because their bytes (hashed into every result file) are kept, and
// tests/machine_parameters_test.cpp holds them to this list.
#define NCUBE_NETWORK_MODEL(X)                                                                 \
  X("network/model", "CM02",                                                                    \
    "no latency or bandwidth correction factors (SimGrid's default LV08 multiplies latency "    \
    "by 13)")                                                                                   \
  X("network/crosstraffic", "0",                                                                \
    "no reverse acknowledgement flow beside each message")                                      \
  X("network/solver", "fairbottleneck",                                                         \
    "a link is shared equally between the messages crossing it")

struct MachineParameter {
  const char* name;  // in a JSON file's "parameters", an XML <prop>, the result file
  const char* unit;
  double low, high;  // inclusive
  bool whole;        // must be a whole number
  XmlForm xml;
  bool optional;     // may be left out of a platform file (then 0: the kind runs at node_speed)
  const char* doc;
  bool integral;     // held as an int (the result file writes it without a fraction)
  double (*get)(const PlatformConfig&);
  void (*set)(PlatformConfig&, double);
};

// Every parameter, in the list's order.
const std::vector<MachineParameter>& machine_parameters();

// What the loaders hold a value to: name, range, whole number, unit.
ParameterSpec parameter_spec(const MachineParameter& parameter);

// Whether a platform of `format` ("json" or "simgrid-xml") gives the parameter a value.
bool carried_by(const MachineParameter& parameter, const std::string& format);

// NCUBE_NETWORK_MODEL as SimGrid settings.
const std::map<std::string, std::string>& default_network_model();

}  // namespace ncube

// A SimGrid XML platform file is untrusted input, as a model is (docs/platforms.md, "What a
// platform file may hold"): researchers share them. SimGrid's own parser recurses on nested
// zones, builds every host a few bytes of topology ask for before it checks anything, and
// aborts (SIGABRT) on a NaN bandwidth, a malformed DragonFly string or a trace that turns a
// node off. So the file's shape is checked here on its text, before SimGrid sees it, and its
// values after SimGrid has read their units:
//  - nesting: at most kMaxPlatformDepth levels of elements;
//  - size: at most kMaxPlatformHosts hosts, counted from <host> tags and each <cluster>'s
//    radical and topology (TORUS, FAT_TREE, DRAGONFLY: their strings validated, and the
//    topology's host count equal to the radical's);
//  - numbers: every bandwidth, latency and speed attribute's number finite and not negative;
//  - no <trace> or <trace_connect> (a node's or link's values changing during the run);
//  - after loading: every link's bandwidth and latency within the machine parameters' ranges
//    (link_bandwidth, hop_latency: machine_parameters.h; the hosts, all nodes, are held to
//    node_speed's with the other node values).
#pragma once

#include <string>

namespace simgrid::s4u {
class Engine;
}

namespace ncube {

// Far above any machine of the studies: the nCube2 family's largest is 8,192 nodes (d13), a
// SimGrid host with its links takes about 10 KB, and zones are a few levels deep.
inline constexpr int kMaxPlatformDepth = 64;
inline constexpr long kMaxPlatformHosts = 65536;

// The hosts the file builds, counted without building them; throws InputError naming the
// file, line or element and the limit for anything above.
long check_platform_shape(const std::string& path, const std::string& text);

// After SimGrid loaded the file: every link's values within the machine parameters' ranges;
// throws InputError naming the link.
void check_platform_values(const std::string& path, simgrid::s4u::Engine& engine);

}  // namespace ncube

// The nCube2 network as a SimGrid platform: a binary hypercube of 2^dimension nodes with
// e-cube (dimension-order) routing, full-duplex links and the constant latency-plus-bandwidth
// model, so that S bytes over h hops take h x hop_latency + S / link_bandwidth.
#pragma once

#include <vector>

#include <simgrid/s4u/Engine.hpp>
#include <simgrid/s4u/Host.hpp>

#include "machine/platform_config.h"

namespace ncube {

// Builds the hypercube; node k is host "node-k" and has index k in the result.
std::vector<simgrid::s4u::Host*> build_hypercube(const PlatformConfig& config);

// Hops of the e-cube route between two nodes: the number of differing address bits.
int hypercube_hops(int from, int to);

}  // namespace ncube

// Marks a header as host-side speed machinery (src/host/): code that only computes the
// simulated program's answers fast on this computer (Embree, host threads, caches, computing
// ahead). It may change no answer, no count, no message and no simulated second.
//
// The simulated side (the ncube_model library: src/geometry, scene, radiosity, visibility,
// machine, nodes, render, util) is compiled with NCUBE_SIMULATED_SIDE defined, so including a
// host header there stops the build here (tests/seam_test.sh checks that every host header
// includes this one).
#pragma once

#ifdef NCUBE_SIMULATED_SIDE
#error "a host-side header (src/host/) was included from the simulated side; see docs/architecture.md"
#endif

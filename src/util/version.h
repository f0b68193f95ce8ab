// The versions a result file records (docs/result-format.md, "provenance").
#pragma once

#include <string>

namespace ncube {

// `git describe --always --dirty` of the source tree at build time, "unknown" without git.
std::string code_version();

// The SimGrid library the simulator runs on, e.g. "3.32.0".
std::string simgrid_version();

}  // namespace ncube

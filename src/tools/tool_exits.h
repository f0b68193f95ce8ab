// The one catch ladder of the command-line tools (./simulate, network_bench, reference_solution,
// machine_probe): every exception ends in one line on stderr, "TOOL: message", and its own
// exit code (docs/cli.md, "Exit codes"); the output files are removed as the stack unwinds.
#pragma once

#include <functional>

namespace ncube {

// What a std::runtime_error that is none of the project's own errors means for a tool: a bug
// (exit 7), or, for a tool whose runs SimGrid ends by throwing one (network_bench), a failed
// simulation (exit 4).
enum class OtherRuntimeErrors { kInternalError, kSimulationFailed };

int run_tool(const char* tool, const std::function<int()>& run,
              OtherRuntimeErrors other = OtherRuntimeErrors::kInternalError);

}  // namespace ncube

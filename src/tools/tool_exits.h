// The one catch ladder of the command-line tools (./simulate, network_bench, reference_solution,
// machine_probe): every exception ends in one line on stderr, "TOOL: message", and its own
// exit code (docs/cli.md, "Exit codes"); the output files are removed as the stack unwinds.
#pragma once

#include <functional>
#include <optional>

namespace CLI {
class App;
}

namespace ncube {

// What a std::runtime_error that is none of the project's own errors means for a tool: a bug
// (exit 7), or, for a tool whose runs SimGrid ends by throwing one (network_bench), a failed
// simulation (exit 4).
enum class OtherRuntimeErrors { kInternalError, kSimulationFailed };

int run_tool(const char* tool, const std::function<int()>& run,
              OtherRuntimeErrors other = OtherRuntimeErrors::kInternalError);

// The command line parsed as every tool parses it: --help and --version print and end the
// run (exit 0), a bad option is one line, "(see TOOL --help)" and exit 2. Returns the exit
// code when the run ends here, nothing when it goes on.
std::optional<int> parse_command_line(CLI::App& app, const char* tool, int argc, char** argv);

}  // namespace ncube

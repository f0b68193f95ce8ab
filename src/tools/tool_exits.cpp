#include "tools/tool_exits.h"

#include <CLI/CLI.hpp>

#include <iostream>
#include <new>
#include <stdexcept>

#include "util/input_error.h"

namespace ncube {

int run_tool(const char* tool, const std::function<int()>& run, OtherRuntimeErrors other) {
  const std::string prefix = std::string(tool) + ": ";
  try {
    return run();
  } catch (const InputError& e) {
    std::cerr << prefix << e.what() << "\n";
    return kExitBadInput;
  } catch (const OutputError& e) {
    std::cerr << prefix << e.what() << " (no output file was written)\n";
    return kExitCannotWrite;
  } catch (const HostMemoryError& e) {
    std::cerr << prefix << e.what() << " (no output file was written)\n";
    return kExitHostOutOfMemory;
  } catch (const std::bad_alloc&) {
    std::cerr << prefix << "the host ran out of memory (no output file was written)\n";
    return kExitHostOutOfMemory;
  } catch (const std::runtime_error& e) {
    if (other == OtherRuntimeErrors::kSimulationFailed) {
      std::cerr << prefix << "the simulation failed: " << e.what() << "\n";
      return kExitSimulationFailed;
    }
    std::cerr << prefix << "internal error: " << e.what() << "\n";
    return kExitInternalError;
  } catch (const std::exception& e) {
    std::cerr << prefix << "internal error: " << e.what() << "\n";
    return kExitInternalError;
  } catch (...) {
    std::cerr << prefix << "internal error: an unknown exception\n";
    return kExitInternalError;
  }
}

std::optional<int> parse_command_line(CLI::App& app, const char* tool, int argc, char** argv) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    std::cout << app.help();
    return kExitOk;
  } catch (const CLI::CallForVersion& e) {
    std::cout << e.what() << "\n";
    return kExitOk;
  } catch (const CLI::ParseError& e) {
    std::cerr << tool << ": " << e.what() << "\n(see " << tool << " --help)\n";
    return kExitBadInput;
  }
  return std::nullopt;
}

}  // namespace ncube

#include "tools/tool_exits.h"

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

}  // namespace ncube

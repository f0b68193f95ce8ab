// Bad input of any kind (scene, platform, cost model, command line). The message names the
// file, the item and the field; the command-line tools turn it into exit code 2 and write
// no output file.
#pragma once

#include <stdexcept>
#include <string>

namespace ncube {

class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// An output file that could not be written after the run (disk full, file-size limit, I/O
// error); the command-line tools turn it into exit code 5 and leave no output file.
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The host running the tool has not the memory a run needs, known before it is taken (an
// estimate against what the host has): exit code 6 with this message, as std::bad_alloc.
class HostMemoryError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Exit codes of the command-line tools (documented in docs/cli.md).
constexpr int kExitOk = 0;
constexpr int kExitBadInput = 2;
constexpr int kExitOutOfMemory = 3;       // a simulated node's memory (the model)
constexpr int kExitSimulationFailed = 4;  // a node did not finish, or a result is not finite
constexpr int kExitCannotWrite = 5;       // an output file could not be written
constexpr int kExitHostOutOfMemory = 6;   // the host running the simulator (std::bad_alloc)
constexpr int kExitInternalError = 7;     // any other exception: a bug of the simulator

}  // namespace ncube

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

// Exit codes of the command-line tools (documented in docs/cli.md).
constexpr int kExitOk = 0;
constexpr int kExitBadInput = 2;
constexpr int kExitOutOfMemory = 3;

}  // namespace ncube

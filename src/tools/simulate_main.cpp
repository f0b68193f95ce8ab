// ./simulate [options] SCENE.json — one simulated run of the paper's radiosity program on
// the modeled nCube2; prints a summary, optionally writes the result file and a picture.
// The command itself is tools/simulate_command.cpp.
#include "tools/simulate_command.h"
#include "tools/tool_exits.h"

int main(int argc, char** argv) {
  // Every exception ends in one message and its own exit code (docs/cli.md); the output
  // files are removed as the stack unwinds.
  return ncube::run_tool("simulate", [&] { return ncube::simulate_command(argc, argv); });
}

// ./simulate [options] SCENE.json — one simulated run of the paper's radiosity program on
// the modeled nCube2; prints a summary, optionally writes the result file and a picture.
// The command itself is tools/simulate_command.cpp.
#include "tools/simulate_command.h"

int main(int argc, char** argv) { return ncube::simulate_main(argc, argv); }

// ./simulate's command as a function, so that a program that has already loaded SimGrid (a test
// forked after the libraries' start-up, tests/simgrid_setting_ranges_test.cpp) runs exactly
// what ./simulate runs from the same arguments, without a new process's start-up.
#pragma once

namespace ncube {

// One run of ./simulate from its command line (argv[0] is the program's name); returns the
// exit code (docs/cli.md) or throws: run_tool("simulate", ...) (tools/tool_exits.h) turns
// what it throws into one message and its exit code, as ./simulate's main does. At most one
// call in a process (SimGrid allows one Engine a process).
int simulate_command(int argc, char** argv);

// ./simulate's main: simulate_command with what it throws turned into one message and its exit
// code. Also what tests/simulate_server.cpp runs in each forked case.
int simulate_main(int argc, char** argv);

}  // namespace ncube

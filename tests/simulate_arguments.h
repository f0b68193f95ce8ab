// The tests of the method registries (visibility, form factors, parallelisations) parse
// simulate's command line the same way: one helper, so they check the same thing.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tools/simulate_options.h"

namespace ncube {

// simulate's options for `args` (after a scene name), and its exit status; what it printed
// to standard output in *out.
inline int parse(std::vector<std::string> args, SimulateOptions& options, std::string* out = nullptr) {
  args.insert(args.begin(), {"simulate", "scene0.json"});
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  testing::internal::CaptureStdout();
  testing::internal::CaptureStderr();
  const int status = parse_simulate_options(int(argv.size()), argv.data(), options);
  const std::string printed = testing::internal::GetCapturedStdout();
  testing::internal::GetCapturedStderr();
  if (out) *out = printed;
  return status;
}

}  // namespace ncube

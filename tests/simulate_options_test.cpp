// The command-line options of simulate: counts are decimal, the iteration count and the
// convergence fraction are in range, output file names are not empty.
#include "tools/simulate_options.h"

#include <gtest/gtest.h>

#include <vector>

#include "util/input_error.h"

namespace ncube {
namespace {

// The exit status parse_simulate_options returns for `simulate scene0.json <args>`
// (-1: go on and simulate).
int parse(std::vector<std::string> args, SimulateOptions* parsed = nullptr) {
  args.insert(args.begin(), {"simulate", "scene0.json"});
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  SimulateOptions options;
  testing::internal::CaptureStderr();
  const int status = parse_simulate_options(int(argv.size()), argv.data(), options);
  testing::internal::GetCapturedStderr();
  if (parsed) *parsed = options;
  return status;
}

TEST(SimulateOptions, CountsAreDecimal) {
  SimulateOptions options;
  ASSERT_EQ(parse({"--R", "10"}, &options), -1);
  EXPECT_EQ(options.config.radiosity_processors, 10);
  // CLI11 reads "010" as 8 (octal) and "0x10" as 16.
  for (const char* bad : {"010", "0x10", "0b11", "1e3", " 4", "+4", ""})
    EXPECT_EQ(parse({"--R", bad}), kExitBadInput) << bad;
  EXPECT_EQ(parse({"--samples", "016"}), kExitBadInput);
  EXPECT_EQ(parse({"--block-size", "010"}), kExitBadInput);
}

// The defaults are the configuration's own (one per value): blocks of 100 points (section
// 3: "blocks of e.g. 100"), not pipelined, memory capped, no subdivision, no balancing, an
// 800 x 600 picture; the options given reach the configuration the node programs are set up
// from, and the loads travel with the candidates when subdivision or balancing is on.
TEST(SimulateOptions, DefaultsAndOptionsReachTheProgramSetup) {
  SimulateOptions options;
  ASSERT_EQ(parse({}, &options), -1);
  const Scene scene;
  const ProgramSetup defaults{scene, Placement{1, 0}, options.config, 1.0};
  EXPECT_EQ(defaults.block_size, 100);
  EXPECT_FALSE(defaults.pipelined);
  EXPECT_EQ(defaults.options.samples, 64);  // the calibrated setup (docs/reproduce.md)
  EXPECT_TRUE(defaults.memory_cap);
  EXPECT_FALSE(defaults.options.subdivision.enabled);  // sections 4.1 and 4.2 off by default
  EXPECT_FALSE(defaults.balancing.enabled);
  EXPECT_DOUBLE_EQ(defaults.balancing.threshold, 0.2);
  EXPECT_FALSE(defaults.loads_change());
  EXPECT_EQ(options.config.render.width, 800);
  EXPECT_EQ(options.config.render.height, 600);
  ASSERT_EQ(parse({"--block-size", "37", "--pipelined", "--samples", "16", "--image-width", "320",
                   "--image-height", "200", "--unlimited-memory", "--balance",
                   "--balance-threshold", "0.5"},
                  &options),
            -1);
  const ProgramSetup given{scene, Placement{1, 0}, options.config, 1.0};
  EXPECT_EQ(given.block_size, 37);
  EXPECT_TRUE(given.pipelined);
  EXPECT_EQ(given.options.samples, 16);
  EXPECT_FALSE(given.memory_cap);
  EXPECT_TRUE(given.balancing.enabled);
  EXPECT_DOUBLE_EQ(given.balancing.threshold, 0.5);
  EXPECT_TRUE(given.loads_change());
  SimulateOptions subdividing;
  ASSERT_EQ(parse({"--subdivide"}, &subdividing), -1);
  EXPECT_TRUE(ProgramSetup(scene, Placement{1, 0}, subdividing.config, 1.0).loads_change());
  EXPECT_EQ(options.config.render.width, 320);
  EXPECT_EQ(options.config.render.height, 200);
}

TEST(SimulateOptions, IterationsAreMinusOneOrACount) {
  SimulateOptions options;
  ASSERT_EQ(parse({"--iterations", "-1"}, &options), -1);
  EXPECT_EQ(options.config.options.max_iterations, -1);
  ASSERT_EQ(parse({"--iterations", "0"}, &options), -1);
  EXPECT_EQ(options.config.options.max_iterations, 0);
  // -5 used to mean "until converged" silently.
  EXPECT_EQ(parse({"--iterations", "-5"}), kExitBadInput);
  EXPECT_EQ(parse({"--iterations", "-2"}), kExitBadInput);
}

TEST(SimulateOptions, ConvergenceFractionIsReachable) {
  SimulateOptions options;
  ASSERT_EQ(parse({"--convergence", "1e-10"}, &options), -1);
  EXPECT_EQ(options.config.options.convergence_fraction, 1e-10);
  ASSERT_EQ(parse({"--convergence", "1"}, &options), -1);
  // 0, NaN and 1e-300 passed the old range check, and the run never stopped.
  for (const char* bad : {"0", "nan", "1e-300", "1e-400", "-1", "2", "inf", "abc", ""})
    EXPECT_EQ(parse({"--convergence", bad}), kExitBadInput) << bad;
}

TEST(SimulateOptions, OutputFileNamesAreNotEmpty) {
  // --json "" was silently "no result file".
  for (const char* option : {"--json", "--trace", "--image"})
    EXPECT_EQ(parse({option, ""}), kExitBadInput) << option;
}

}  // namespace
}  // namespace ncube

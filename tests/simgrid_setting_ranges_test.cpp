// The table of SimGrid settings a run survives (src/machine/simgrid_setting_ranges.h):
//  - it has one row for every key SimGrid lists in its --help, and no row for a key SimGrid
//    does not know (SimGrid is asked in a child process, as ./simulate's check asks it);
//  - every value that ended a run in SIGSEGV, abort, exit 7 or a hang (issue 30, and the
//    survey of every key by its type) is refused with one line naming the setting, the value
//    and the valid range;
//  - each range's ends and every choice run a small simulation to its end (exit 0): the
//    table's ranges are proven, not guessed. Each is ./simulate's command run in a forked
//    child (tools/simulate_command.h), not a new ./simulate process.
// Each test runs in its own process (ctest), with no Engine yet.
#include "machine/simgrid_setting_ranges.h"

#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <set>
#include <simgrid/s4u/Engine.hpp>
#include <sstream>

#include "machine/simgrid_platform_file.h"
#include "machine/simgrid_settings.h"
#include "tools/simulate_command.h"
#include "util/input_error.h"

namespace ncube {
namespace {

// What SimGrid prints for `option` (--help, --help-aliases), read from a child that runs it.
std::string simgrid_says(const char* option) {
  int ends[2];
  if (pipe(ends) != 0) return {};
  const pid_t child = fork();
  if (child == 0) {
    close(ends[0]);
    dup2(ends[1], STDOUT_FILENO);
    dup2(ends[1], STDERR_FILENO);
    std::string name = "simulate", help = option;
    char* argv[] = {name.data(), help.data(), nullptr};
    int argc = 2;
    simgrid::s4u::Engine engine(&argc, argv);  // prints the settings and exits
    _exit(1);
  }
  close(ends[1]);
  std::string text;
  char buffer[4096];
  for (ssize_t n; (n = read(ends[0], buffer, sizeof buffer)) > 0;) text.append(buffer, std::size_t(n));
  close(ends[0]);
  waitpid(child, nullptr, 0);
  return text;
}

// The keys SimGrid's --help lists ("   name: description").
std::set<std::string> keys_simgrid_lists() {
  std::set<std::string> keys;
  std::istringstream lines(simgrid_says("--help"));
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("   ", 0) != 0 || line.size() < 4 || line[3] == ' ') continue;
    const std::size_t colon = line.find(": ");
    if (colon != std::string::npos) keys.insert(line.substr(3, colon - 3));
  }
  return keys;
}

TEST(SimgridSettingRanges, EveryKeySimgridListsHasOneRow) {
  const std::set<std::string> listed = keys_simgrid_lists();
  ASSERT_GT(listed.size(), 90u) << "SimGrid's --help was not read";
  std::set<std::string> rows;
  for (const SimgridSettingRange& range : simgrid_setting_ranges()) {
    EXPECT_TRUE(rows.insert(std::string(range.name)).second) << "two rows for " << range.name;
    EXPECT_FALSE(range.why.empty()) << range.name << " has no reason";
  }
  for (const std::string& key : listed)
    EXPECT_TRUE(rows.count(key)) << "SimGrid lists " << key << ", the table has no row for it";
  for (const std::string& row : rows)
    EXPECT_TRUE(listed.count(row)) << "the table's " << row << " is not a SimGrid setting";
}

// An old name SimGrid still takes ("   OLD-NAME   NEW-NAME") would pass the table unchecked:
// SimGrid 3.32 has none, and one added by an upgrade must get a row.
TEST(SimgridSettingRanges, EveryAliasSimgridTakesHasARow) {
  const std::string said = simgrid_says("--help-aliases");
  ASSERT_NE(said.find("list of all deprecated option names"), std::string::npos) << said;
  std::istringstream lines(said);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("   ", 0) != 0) continue;
    std::istringstream words(line);
    std::string alias;
    words >> alias;
    EXPECT_NE(simgrid_setting_range(alias), nullptr) << "SimGrid takes " << alias << ", no row";
  }
}

std::string refusal(const std::string& argument) {
  try {
    check_simgrid_settings({argument});
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// Every value below ended a run of scene0 (R=2 V=1, 2 iterations) in SIGSEGV (139), abort
// (134), SIGTRAP-free exit 7, a SimGrid deadlock (exit 4) or a hang, with SimGrid 3.32.
TEST(SimgridSettingRanges, ValuesThatEndedARunAreRefusedWithTheRange) {
  for (const char* setting :
       {"maxmin/precision:nan", "maxmin/precision:1e300", "maxmin/precision:1",
        "maxmin/precision:-1", "maxmin/precision:inf", "network/model:ns-3",
        "network/model:Constant", "contexts/stack-size:1", "contexts/stack-size:64",
        "contexts/stack-size:2147483647", "contexts/stack-size:-1", "contexts/nthreads:8",
        "contexts/nthreads:2147483647", "contexts/guard-size:-1",
        "contexts/guard-size:2147483647", "network/bandwidth-factor:0",
        "network/bandwidth-factor:nan", "network/bandwidth-factor:-1",
        "network/latency-factor:inf", "maxmin/concurrency-limit:0", "surf/precision:0",
        "surf/precision:nan", "surf/precision:-1", "bmf/max-iterations:0",
        "bmf/max-iterations:-1", "plugin:cmonkey", "plugin/dvfs/max-pstate:5",
        "plugin/dvfs/min-pstate:1", "plugin/dvfs/sampling-rate:nan",
        "plugin/dvfs/sampling-rate:1e-5", "plugin/dvfs/sampling-rate:0",
        "smpi/bw-factor:bogus", "smpi/bw-factor:0:nan", "smpi/lat-factor:bogus",
        "smpi/lat-factor:-1:2", "smpi/IB-penalty-factors:bogus", "smpi/IB-penalty-factors:1;2",
        "model-check/replay:1", "tracing/comment-file:/nonexistent", "tracing/vm:yes"}) {
    const std::string argument = std::string("--cfg=") + setting;
    const std::string message = refusal(argument);
    const std::string name(setting, std::string(setting).find(':'));
    EXPECT_EQ(message.rfind(argument + ": " + name + " must be ", 0), 0u)
        << argument << " gave: " << (message.empty() ? "no refusal" : message);
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

TEST(SimgridSettingRanges, TheMessageGivesTheRange) {
  EXPECT_EQ(refusal("--cfg=maxmin/precision:nan").substr(0, 85),
            "--cfg=maxmin/precision:nan: maxmin/precision must be a finite number in [1e-15, 0.01]");
  EXPECT_NE(refusal("--cfg=network/model:ns-3").find("must be one of LV08, CM02, SMPI, IB ("),
            std::string::npos);
  EXPECT_NE(refusal("--cfg=contexts/stack-size:1").find("a whole number in [1024, 65536]"),
            std::string::npos);
  EXPECT_NE(refusal("--cfg=maxmin/concurrency-limit:0").find("-1 (none) or a whole number in [1, "
                                                             "2147483647]"),
            std::string::npos);
}

TEST(SimgridSettingRanges, ValuesInsideAreTaken) {
  for (const char* setting :
       {"maxmin/precision:1e-5", "maxmin/precision:1e-15", "maxmin/precision:0.01",
        "network/model:CM02", "contexts/stack-size:8192", "contexts/nthreads:1",
        "maxmin/concurrency-limit:-1", "maxmin/concurrency-limit:4",
        "smpi/bw-factor:65472:0.94;0:0.81", "smpi/IB-penalty-factors:0.965;0.925;1.35",
        "tracing/vm:no", "debug/breakpoint:-1", "smpi/np:-5"})
    EXPECT_EQ(refusal(std::string("--cfg=") + setting), "") << setting;
}

// A SimGrid platform file's <config> tags are settings too: held to the same table before
// SimGrid loads the file (Constant aborts while it loads).
TEST(SimgridSettingRanges, APlatformFilesConfigTagsAreChecked) {
  const std::filesystem::path file = std::filesystem::path(testing::TempDir()) / "config_tag.xml";
  std::ifstream in(std::string(NCUBE_SOURCE_DIR) + "/platforms/ncube2.xml");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string model = "<prop id=\"network/model\" value=\"CM02\"/>";
  ASSERT_NE(text.find(model), std::string::npos);
  text.replace(text.find(model), model.size(), "<prop id=\"network/model\" value=\"Constant\"/>");
  std::ofstream(file) << text;
  try {
    read_simgrid_platform_file(file.string(), {});
    ADD_FAILURE() << "network/model Constant in <config> was taken";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(file.string() + ": <config> <prop id=\"network/model\" "
                                          "value=\"Constant\">: network/model must be one of",
                                          0),
              0u)
        << e.what();
  }
  std::filesystem::remove(file);
}

// Settings read only with a model, solver or plugin are run with it.
std::vector<std::string> companion(std::string_view name) {
  if (name.rfind("bmf/", 0) == 0) return {"--cfg=network/solver:bmf", "--cfg=cpu/solver:bmf"};
  if (name.rfind("plugin/dvfs/", 0) == 0) return {"--cfg=plugin:host_dvfs"};
  if (name == "smpi/bw-factor" || name == "smpi/lat-factor") return {"--cfg=network/model:SMPI"};
  if (name == "smpi/IB-penalty-factors") return {"--cfg=network/model:IB"};
  if (name == "network/TCP-gamma" || name == "network/weight-S") return {"--cfg=network/model:LV08"};
  if (name.rfind("tracing/", 0) == 0) return {"--cfg=tracing:yes", "--cfg=tracing/actor:yes"};
  return {};
}

std::string text(double value) {
  std::ostringstream out;
  out << std::setprecision(17) << value;
  return out.str();
}

// The values of a row to run: a range's two ends, every choice.
std::vector<std::string> ends_of(const SimgridSettingRange& range) {
  switch (range.kind) {
    case SettingKind::kInteger:
    case SettingKind::kReal:
      return {text(range.low), text(range.high)};
    case SettingKind::kIntegerOrNone:
      return {"-1", text(range.low)};
    case SettingKind::kChoice: {
      std::vector<std::string> choices;
      std::string all(range.choices);
      for (std::size_t start = 0, end; start <= all.size(); start = end + 1) {
        end = all.find(',', start);
        if (end == std::string::npos) end = all.size();
        choices.push_back(all.substr(start, end - start));
      }
      return choices;
    }
    case SettingKind::kFactorList:
      return {"0:1e-6", "65472:1e6;0:2"};
    case SettingKind::kThreeFactors:
      return {"1e-6;1e-6;1e-6", "1e6;1e6;1e6"};
    default:
      return {};
  }
}

// ./simulate's command (tools/simulate_command.h) run from `arguments` in a child forked from
// this process, in `dir`, output to /dev/null and `dir`/run.err: what ./simulate runs, without
// a new process loading SimGrid and ns-3 for each of the ~190 values (about 0.1 CPU-second
// each, before main). This process has no Engine yet (unit_main.cpp forks each test before
// one exists). Returns the child's wait status; a child still running after 60 s is killed.
int simulate_in_child(const std::filesystem::path& dir, std::vector<std::string> arguments) {
  std::fflush(nullptr);
  const pid_t child = fork();
  if (child == 0) {
    if (chdir(dir.c_str()) != 0) _exit(100);
    if (!std::freopen("/dev/null", "w", stdout) || !std::freopen("run.err", "w", stderr)) _exit(101);
    alarm(60);  // SIGALRM ends a hang, as `timeout 60` did
    arguments.insert(arguments.begin(), "simulate");
    std::vector<char*> argv;
    for (std::string& argument : arguments) argv.push_back(argument.data());
    argv.push_back(nullptr);
    const int code = simulate_main(int(arguments.size()), argv.data());
    std::fflush(nullptr);
    _exit(code);
  }
  int status = -1;
  if (child > 0) waitpid(child, &status, 0);
  return status;
}

TEST(SimgridSettingRanges, EveryRangesEndsRunASimulation) {
  const std::filesystem::path dir = std::filesystem::path(testing::TempDir()) / "setting_ranges";
  std::filesystem::create_directories(dir);
  int runs = 0;
  for (const SimgridSettingRange& range : simgrid_setting_ranges())
    for (const std::string& value : ends_of(range)) {
      // Unbounded integers' top end (2^31-1) is not a resource size: no need to run it.
      if (range.high == 2147483647 && value == "2147483647") continue;
      std::vector<std::string> arguments = {"scene0.json", "--R", "2", "--V", "1", "--iterations",
                                            "1", "--quiet",
                                            "--cfg=" + std::string(range.name) + ":" + value};
      for (const std::string& setting : companion(range.name)) arguments.push_back(setting);
      const int status = simulate_in_child(dir, arguments);
      // The TI trace format writes a folder of files per actor, which the output rule refuses
      // (docs/cli.md, "Output files"): exit 2 before the run, not a crash.
      const int expected = std::string(range.name) == "tracing/smpi/format" && value == "TI" ? 2 : 0;
      std::string command = "simulate";
      for (const std::string& argument : arguments) command += " " + argument;
      EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == expected)
          << command << " (status " << status << ")";
      ++runs;
    }
  std::filesystem::remove_all(dir);
  EXPECT_GT(runs, 80);
}

}  // namespace
}  // namespace ncube

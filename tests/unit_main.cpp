// The unit tests' main: gtest's own, plus `--suite NAME`, which runs every test of one suite,
// each in a forked child of this process.
//
// Why: SimGrid allows one Engine per process, so every test needs a process of its own. Started
// from scratch, each such process loads SimGrid, ns-3, Embree and Assimp and runs their static
// initialisers (about 0.1 CPU-second, most of the suite's time for its ~500 short tests). A
// child forked after that start-up has them already, and is as isolated as a new process: one
// Engine, its own memory, a crash of its own. ctest registers one test per suite
// (cmake/unit_suites.cmake); `unit_tests --gtest_filter=Suite.Name` still runs one test the
// usual way.
//
// The children of one suite share a scratch folder, named by NCUBE_SUITE_SCRATCH and removed
// when the suite ends, where a fixture may keep what every test of the suite reads and none
// changes (a run of ./simulate: suite_scratch.h).
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace {

// The exit code a child gives for a skipped test (ctest's SKIP_RETURN_CODE for a whole suite).
constexpr int kSkipped = 77;

struct Outcome {
  std::string name;
  int status;  // 0 passed, kSkipped skipped, otherwise failed
  std::string how;
};

std::vector<std::string> tests_of(const std::string& suite) {
  std::vector<std::string> names;
  const testing::UnitTest& all = *testing::UnitTest::GetInstance();
  for (int i = 0; i < all.total_test_suite_count(); ++i) {
    const testing::TestSuite& s = *all.GetTestSuite(i);
    if (suite != s.name()) continue;
    for (int j = 0; j < s.total_test_count(); ++j)
      names.push_back(suite + "." + s.GetTestInfo(j)->name());
  }
  return names;
}

// Runs one test in a forked child; the child's exit code says passed, skipped or failed.
Outcome run_in_child(const std::string& name) {
  std::fflush(nullptr);
  const pid_t pid = fork();
  if (pid < 0) return {name, 1, std::string("fork failed: ") + std::strerror(errno)};
  if (pid == 0) {
    GTEST_FLAG_SET(filter, name);
    const int failed = RUN_ALL_TESTS();
    const testing::UnitTest& all = *testing::UnitTest::GetInstance();
    std::fflush(nullptr);
    _exit(failed != 0 ? 1 : (all.skipped_test_count() > 0 ? kSkipped : 0));
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (WIFSIGNALED(status))
    return {name, 1, std::string("killed by signal ") + strsignal(WTERMSIG(status))};
  const int code = WIFEXITED(status) ? WEXITSTATUS(status) : 1;
  if (code == 0 || code == kSkipped) return {name, code, ""};
  return {name, 1, "exit " + std::to_string(code)};
}

int run_suite(const std::string& suite) {
  const std::vector<std::string> names = tests_of(suite);
  if (names.empty()) {
    std::fprintf(stderr, "unit_tests: --suite %s: no such test suite (--gtest_list_tests lists them)\n",
                 suite.c_str());
    return 2;
  }
  std::string scratch = (std::filesystem::path(testing::TempDir()) / "suite_XXXXXX").string();
  if (!mkdtemp(scratch.data())) {
    std::fprintf(stderr, "unit_tests: cannot create %s: %s\n", scratch.c_str(), std::strerror(errno));
    return 1;
  }
  setenv("NCUBE_SUITE_SCRATCH", scratch.c_str(), 1);
  const auto start = std::chrono::steady_clock::now();
  std::vector<Outcome> failed, skipped;
  for (const std::string& name : names) {
    Outcome outcome = run_in_child(name);
    if (outcome.status == kSkipped) skipped.push_back(outcome);
    else if (outcome.status != 0) failed.push_back(outcome);
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::error_code ignored;
  std::filesystem::remove_all(scratch, ignored);
  std::printf("\n%s: %zu tests, each in its own process, %.2f s: %zu passed, %zu skipped, %zu failed\n",
              suite.c_str(), names.size(), seconds, names.size() - failed.size() - skipped.size(),
              skipped.size(), failed.size());
  for (const Outcome& o : skipped) std::printf("  skipped %s\n", o.name.c_str());
  for (const Outcome& o : failed)
    std::printf("  FAILED  %s%s%s\n", o.name.c_str(), o.how.empty() ? "" : ": ", o.how.c_str());
  if (!failed.empty()) return 1;
  return skipped.size() == names.size() ? kSkipped : 0;
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--suite") == 0) {
      if (i + 1 >= argc || argc != 3) {
        std::fprintf(stderr, "unit_tests: usage: unit_tests --suite NAME (alone)\n");
        return 2;
      }
      return run_suite(argv[i + 1]);
    }
  }
  return RUN_ALL_TESTS();
}

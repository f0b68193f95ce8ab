// The output files of a run: checked before the run, written all or nothing.
#include "tools/output_files.h"

#include <gtest/gtest.h>
#include <sys/resource.h>

#include <csignal>
#include <filesystem>
#include <fstream>

#include "util/input_error.h"

namespace ncube {
namespace {

namespace fs = std::filesystem;

struct OutputFilesTest : testing::Test {
  fs::path dir;
  void SetUp() override {
    dir = fs::path(testing::TempDir()) /
          ("output_files_" + std::string(testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::ofstream(dir / "scene.json") << "{}";
  }
  void TearDown() override { fs::remove_all(dir); }
  std::string at(const std::string& name) const { return (dir / name).string(); }
  // The InputError message of creating outputs {--json a, --trace b, --image c}.
  std::string error_of(const std::string& json, const std::string& trace = "",
                       const std::string& image = "") const {
    try {
      OutputFiles outputs({{"--json", json}, {"--trace", trace}, {"--image", image}}, {at("scene.json")});
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
  std::size_t files() const {
    return std::size_t(std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
  }
};

TEST_F(OutputFilesTest, WritesAllOutputsOnCommit) {
  {
    OutputFiles outputs({{"--json", at("a.json")}, {"--trace", at("b.json")}}, {at("scene.json")});
    outputs.write("--json", "result");
    outputs.write("--trace", "trace");
    EXPECT_FALSE(fs::exists(at("a.json")));  // nothing visible before the commit
    outputs.commit();
  }
  std::ifstream a(at("a.json"));
  std::string text;
  a >> text;
  EXPECT_EQ(text, "result");
  EXPECT_TRUE(fs::exists(at("b.json")));
  EXPECT_EQ(files(), 3u);  // no temporary file left
}

TEST_F(OutputFilesTest, LeavesNothingWithoutCommit) {
  {
    OutputFiles outputs({{"--json", at("a.json")}, {"--trace", at("b.json")}}, {at("scene.json")});
    outputs.write("--json", "result");
  }  // e.g. an exception in the run
  EXPECT_EQ(files(), 1u);
}

TEST_F(OutputFilesTest, RefusesBadPathsBeforeTheRun) {
  EXPECT_NE(error_of(at("scene.json")).find("is the input file"), std::string::npos);
  EXPECT_NE(error_of(at("./scene.json")).find("is the input file"), std::string::npos);
  EXPECT_NE(error_of(at("x.json"), at("x.json")).find("--trace " + at("x.json") + ": is also another output"),
            std::string::npos);
  EXPECT_NE(error_of(at("nowhere/x.json")).find("does not exist"), std::string::npos);
  EXPECT_NE(error_of(at("scene.json/x.json")).find("is not a folder"), std::string::npos);
  EXPECT_NE(error_of(dir.string()).find("names a folder"), std::string::npos);
  EXPECT_NE(error_of(at("x.json") + "/").find("names a folder"), std::string::npos);
  EXPECT_EQ(files(), 1u);
}

TEST_F(OutputFilesTest, AFailedWriteLeavesNoOutput) {
  // A full disk, as a file-size limit of 1 KB for this test's process.
  std::signal(SIGXFSZ, SIG_IGN);
  const rlimit limit{1024, 1024};
  ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &limit), 0);
  {
    OutputFiles outputs({{"--json", at("a.json")}, {"--trace", at("b.json")}}, {at("scene.json")});
    outputs.write("--json", "small");
    EXPECT_THROW(outputs.write("--trace", std::string(4096, 'x')), OutputError);
  }
  EXPECT_EQ(files(), 1u);
}

}  // namespace
}  // namespace ncube

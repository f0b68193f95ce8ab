// Temporary files: no name until kept, and none left behind by any end of the process.
#include "tools/temporary_file.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace ncube {
namespace {

namespace fs = std::filesystem;

struct TemporaryFileTest : testing::Test {
  fs::path dir;
  void SetUp() override {
    dir = fs::path(testing::TempDir()) /
          ("temporary_file_" + std::string(testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  void TearDown() override { fs::remove_all(dir); }
  std::size_t entries() const {
    return std::size_t(std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
  }
  std::string content_of(const std::string& name) const {
    std::ifstream in(dir / name);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }
  // The status of a child process that makes a temporary file here, writes to it, then
  // ends as `end` says.
  template <typename End>
  int child_status(bool anonymous, End end) const {
    const pid_t child = fork();
    if (child == 0) {
      TemporaryFile file = TemporaryFile::in_folder(dir.string(), "out.json", anonymous);
      file.append("half of it");
      end();
      _exit(0);
    }
    int status = 0;
    waitpid(child, &status, 0);
    return status;
  }
};

TEST_F(TemporaryFileTest, HasNoNameUntilKept) {
  TemporaryFile file = TemporaryFile::in_folder(dir.string(), "out.json");
  EXPECT_FALSE(file.named());
  ASSERT_TRUE(file.append("content"));
  EXPECT_EQ(entries(), 0u);
  ASSERT_TRUE(file.keep_as((dir / "out.json").string()));
  EXPECT_EQ(entries(), 1u);
  EXPECT_EQ(content_of("out.json"), "content");
}

TEST_F(TemporaryFileTest, AnotherWriterWritesThroughItsPath) {
  TemporaryFile file = TemporaryFile::in_folder(dir.string(), "out.log");
  std::FILE* writer = std::fopen(file.writer_path().c_str(), "w");  // as SimGrid opens it
  ASSERT_NE(writer, nullptr);
  std::fputs("logged", writer);
  std::fclose(writer);
  ASSERT_TRUE(file.keep_as((dir / "out.log").string()));
  EXPECT_EQ(content_of("out.log"), "logged");
}

TEST_F(TemporaryFileTest, AFailedRenameLeavesNothing) {
  fs::create_directories(dir / "out.json" / "inside");  // a folder cannot be replaced by a file
  {
    TemporaryFile file = TemporaryFile::in_folder(dir.string(), "out.json");
    file.append("content");
    EXPECT_FALSE(file.keep_as((dir / "out.json").string()));
  }
  EXPECT_EQ(entries(), 1u);  // only the folder
}

TEST_F(TemporaryFileTest, NoEndOfTheProcessLeavesOne) {
  for (bool anonymous : {true, false}) {
    SCOPED_TRACE(anonymous ? "anonymous" : "named");
    int status = child_status(anonymous, [] { std::raise(SIGKILL); });
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL);
    if (anonymous) {
      EXPECT_EQ(entries(), 0u);  // the named form cannot clean up after SIGKILL
    }
    fs::remove_all(dir);
    fs::create_directories(dir);
    for (int signal_number : {SIGSEGV, SIGABRT, SIGTERM, SIGINT, SIGHUP}) {
      status = child_status(anonymous, [signal_number] { std::raise(signal_number); });
      EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == signal_number)
          << "signal " << signal_number << " should still end the process";
      EXPECT_EQ(entries(), 0u) << "signal " << signal_number;
    }
    status = child_status(anonymous, [] { std::exit(1); });  // SimGrid's Ctrl-C handler
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 1);
    EXPECT_EQ(entries(), 0u) << "exit(1)";
  }
}

TEST_F(TemporaryFileTest, TheNamedFormIsKeptToo) {
  TemporaryFile file = TemporaryFile::in_folder(dir.string(), "out.json", false);
  EXPECT_TRUE(file.named());
  EXPECT_EQ(entries(), 1u);
  ASSERT_TRUE(file.append("content"));
  ASSERT_TRUE(file.keep_as((dir / "out.json").string()));
  EXPECT_EQ(entries(), 1u);
  EXPECT_EQ(content_of("out.json"), "content");
}

TEST_F(TemporaryFileTest, AnywhereCopiesOut) {
  TemporaryFile file = TemporaryFile::anywhere();
  EXPECT_FALSE(file.named());
  ASSERT_TRUE(file.append(std::string(200000, 'x')));
  int pipe_ends[2];
  ASSERT_EQ(pipe(pipe_ends), 0);
  const pid_t child = fork();
  if (child == 0) {
    close(pipe_ends[0]);
    _exit(file.copy_to(pipe_ends[1]) ? 0 : 1);
  }
  close(pipe_ends[1]);
  std::string got;
  char buffer[4096];
  for (ssize_t n; (n = read(pipe_ends[0], buffer, sizeof buffer)) > 0;) got.append(buffer, std::size_t(n));
  close(pipe_ends[0]);
  int status = 0;
  waitpid(child, &status, 0);
  EXPECT_EQ(got, std::string(200000, 'x'));
}

}  // namespace
}  // namespace ncube

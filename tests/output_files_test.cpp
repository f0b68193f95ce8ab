// The output files of a run: checked before the run, written all or nothing.
#include "tools/output_files.h"

#include <gtest/gtest.h>
#include <sys/resource.h>

#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/un.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

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
  EXPECT_NE(error_of(at("x.json") + "/").find("names a folder"), std::string::npos);
  EXPECT_EQ(files(), 1u);
}

TEST_F(OutputFilesTest, AFailedWriteLeavesNoOutput) {
  // A full disk, as a file-size limit of 1 KB for this test's process.
  // (Restored after: streamed outputs are written to temporary files too.)
  std::signal(SIGXFSZ, SIG_IGN);
  rlimit before{};
  ASSERT_EQ(getrlimit(RLIMIT_FSIZE, &before), 0);
  const rlimit limit{1024, before.rlim_max};
  ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &limit), 0);
  {
    OutputFiles outputs({{"--json", at("a.json")}, {"--trace", at("b.json")}}, {at("scene.json")});
    outputs.write("--json", "small");
    EXPECT_THROW(outputs.write("--trace", std::string(4096, 'x')), OutputError);
  }
  setrlimit(RLIMIT_FSIZE, &before);
  EXPECT_EQ(files(), 1u);
}

std::string content_of(const fs::path& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// One output, written and committed.
void write_one(const std::string& path, const std::string& content, const std::string& input) {
  OutputFiles outputs({{"--json", path}}, {input});
  outputs.write("--json", content);
  outputs.commit();
}

// The activity record's target became a folder during the run: its rename fails (exit 5),
// and neither its temporary file nor the result file is left.
TEST_F(OutputFilesTest, AFailedRenameLeavesNoTemporaryAndNoOtherOutput) {
  {
    OutputFiles outputs({{"--json", at("r.json")}, {"NCUBE_RECORD_ACTIVITIES", at("run.act")}},
                        {at("scene.json")});
    fs::create_directories(at("run.act/inside"));
    outputs.write("--json", "result");
    outputs.write("NCUBE_RECORD_ACTIVITIES", "record");
    try {
      outputs.commit();
      ADD_FAILURE() << "commit should fail";
    } catch (const OutputError& e) {
      EXPECT_NE(std::string(e.what()).find("NCUBE_RECORD_ACTIVITIES " + at("run.act") + ": cannot rename"),
                std::string::npos) << e.what();
    }
  }
  EXPECT_EQ(files(), 2u);  // scene.json and the folder: no r.json, no temporary file
  EXPECT_FALSE(fs::exists(at("r.json")));
}

// What another writer (SimGrid) writes through writer_path is committed like the rest.
TEST_F(OutputFilesTest, CommitsWhatAnotherWriterWrote) {
  {
    OutputFiles outputs({{"--log=root.app:file:run.log", at("run.log")}}, {at("scene.json")});
    std::FILE* log = std::fopen(outputs.writer_path("--log=root.app:file:run.log").c_str(), "w");
    ASSERT_NE(log, nullptr);
    std::fputs("logged\n", log);  // left buffered: commit flushes it
    EXPECT_EQ(files(), 1u);         // no name yet
    outputs.commit();
    std::fclose(log);
  }
  EXPECT_EQ(content_of(at("run.log")), "logged\n");
  EXPECT_EQ(files(), 2u);
}

TEST_F(OutputFilesTest, FollowsLinksAndKeepsThem) {
  std::ofstream(at("target.json")) << "old";
  fs::create_symlink("target.json", at("link.json"));         // relative
  fs::create_symlink(at("link.json"), at("link-to-link.json"));  // absolute, to a link
  write_one(at("link-to-link.json"), "new", at("scene.json"));
  EXPECT_TRUE(fs::is_symlink(at("link.json")));
  EXPECT_TRUE(fs::is_symlink(at("link-to-link.json")));
  EXPECT_EQ(content_of(at("target.json")), "new");
  EXPECT_EQ(files(), 4u);  // the scene, the target, two links: no temporary file left
}

TEST_F(OutputFilesTest, CreatesTheTargetOfADanglingLink) {
  fs::create_symlink("made.json", at("dangling.json"));
  write_one(at("dangling.json"), "made", at("scene.json"));
  EXPECT_TRUE(fs::is_symlink(at("dangling.json")));
  EXPECT_EQ(content_of(at("made.json")), "made");
}

TEST_F(OutputFilesTest, RefusesALoopOfLinksAndALinkToTheScene) {
  fs::create_symlink("b.json", at("a.json"));
  fs::create_symlink("a.json", at("b.json"));
  EXPECT_NE(error_of(at("a.json")).find("symbolic links"), std::string::npos);
  fs::create_symlink("scene.json", at("to-scene.json"));
  EXPECT_NE(error_of(at("to-scene.json")).find("is the input file"), std::string::npos);
}

TEST_F(OutputFilesTest, RefusesAFolderAndASocketBeforeTheRun) {
  fs::create_directory(at("folder"));
  EXPECT_THROW(OutputFiles({{"--json", at("folder")}}, {at("scene.json")}), OutputError);
  const int s = socket(AF_UNIX, SOCK_STREAM, 0);
  sockaddr_un address{};
  address.sun_family = AF_UNIX;
  const std::string socket_path = at("socket");
  ASSERT_LT(socket_path.size(), sizeof(address.sun_path));
  std::copy(socket_path.begin(), socket_path.end(), address.sun_path);
  ASSERT_EQ(bind(s, reinterpret_cast<sockaddr*>(&address), sizeof(address)), 0);
  EXPECT_THROW(OutputFiles({{"--json", socket_path}}, {at("scene.json")}), OutputError);
  close(s);
  struct stat info {};
  ASSERT_EQ(lstat(socket_path.c_str(), &info), 0);
  EXPECT_TRUE(S_ISSOCK(info.st_mode));  // not replaced
}

TEST_F(OutputFilesTest, StreamsIntoAFifo) {
  ASSERT_EQ(mkfifo(at("fifo").c_str(), 0600), 0);
  std::string received;
  std::thread reader([&] { received = content_of(at("fifo")); });
  write_one(at("fifo"), std::string(100000, 'r'), at("scene.json"));  // more than a pipe holds
  reader.join();
  EXPECT_EQ(received, std::string(100000, 'r'));
  struct stat info {};
  ASSERT_EQ(lstat(at("fifo").c_str(), &info), 0);
  EXPECT_TRUE(S_ISFIFO(info.st_mode));
}

// Character devices made here, never the machine's own /dev: a null device (1, 3) and a full
// one (1, 7). mknod needs root; elsewhere the test says it was skipped.
TEST_F(OutputFilesTest, WritesCharacterDevicesWhereTheyPoint) {
  if (mknod(at("null").c_str(), S_IFCHR | 0666, makedev(1, 3)) != 0 ||
      mknod(at("full").c_str(), S_IFCHR | 0666, makedev(1, 7)) != 0)
    GTEST_SKIP() << "mknod needs root: character devices not tried";
  {
    OutputFiles outputs({{"--json", at("null")}, {"--trace", at("null")}}, {at("scene.json")});
    outputs.write("--json", "discarded");
    outputs.write("--trace", "discarded too");
    outputs.commit();
  }
  {
    OutputFiles outputs({{"--json", at("a.json")}, {"--trace", at("full")}}, {at("scene.json")});
    outputs.write("--json", "result");
    outputs.write("--trace", "trace");
    EXPECT_THROW(outputs.commit(), OutputError);  // ENOSPC
  }
  EXPECT_FALSE(fs::exists(at("a.json")));  // the stream failed first: no file was changed
  for (const char* device : {"null", "full"}) {
    struct stat info {};
    ASSERT_EQ(lstat(at(device).c_str(), &info), 0);
    EXPECT_TRUE(S_ISCHR(info.st_mode)) << device << " was replaced";
  }
}

TEST_F(OutputFilesTest, DashIsStandardOutput) {
  testing::internal::CaptureStdout();
  {
    OutputFiles outputs({{"--json", "-"}, {"--trace", at("b.json")}}, {at("scene.json")});
    EXPECT_TRUE(outputs.uses_standard_output());
    outputs.write("--json", "to stdout");
    outputs.write("--trace", "to a file");
    outputs.commit();
  }
  EXPECT_EQ(testing::internal::GetCapturedStdout(), "to stdout");
  EXPECT_EQ(content_of(at("b.json")), "to a file");
  EXPECT_NE(error_of("-", "-").find("standard output is also another output"), std::string::npos);
}

}  // namespace
}  // namespace ncube

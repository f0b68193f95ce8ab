// The input gate (src/util/input_file.h) with every kind of path: what it reads, and the one
// line it refuses each other kind with, without blocking or reading past the limit.
#include "util/input_file.h"

#include <gtest/gtest.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "util/input_error.h"

namespace ncube {
namespace {

namespace fs = std::filesystem;

constexpr InputKind kTen{"test file", 10};

struct InputFileTest : testing::Test {
  fs::path dir;
  void SetUp() override {
    dir = fs::path(testing::TempDir()) /
          ("input_file_" +
           std::string(testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  void TearDown() override { fs::remove_all(dir); }
  std::string write(const std::string& name, const std::string& text) {
    std::ofstream(dir / name, std::ios::binary) << text;
    return (dir / name).string();
  }
  // The message reading `path` as `kind` ends with, or "read: <contents>".
  static std::string outcome(const std::string& path, const InputKind& kind = kTen) {
    try {
      return "read: " + read_input_file(path, kind, "x.obj: names ");
    } catch (const InputError& e) {
      const std::string message = e.what();
      EXPECT_EQ(message.rfind("x.obj: names " + path + ": ", 0), 0u) << message;
      return message.substr(("x.obj: names " + path + ": ").size());
    }
  }
};

TEST_F(InputFileTest, RegularFileAndLinkToOneAreRead) {
  const std::string file = write("a.txt", "0123456789");  // exactly the limit
  EXPECT_EQ(outcome(file), "read: 0123456789");
  fs::create_symlink(file, dir / "link");
  EXPECT_EQ(outcome((dir / "link").string()), "read: 0123456789");
  EXPECT_EQ(InputFile((dir / "link").string(), kTen).real_path(), fs::canonical(file).string());
}

TEST_F(InputFileTest, DanglingLinkAndLoop) {
  fs::create_symlink(dir / "gone", dir / "dangling");
  EXPECT_EQ(outcome((dir / "dangling").string()),
            "cannot open test file: No such file or directory");
  fs::create_symlink(dir / "loop2", dir / "loop1");
  fs::create_symlink(dir / "loop1", dir / "loop2");
  EXPECT_EQ(outcome((dir / "loop1").string()), "cannot open test file: a loop of symbolic links");
}

TEST_F(InputFileTest, OnlyRegularFiles) {
  // A FIFO with no writer: opening it must not wait for one.
  ASSERT_EQ(mkfifo((dir / "fifo").c_str(), 0600), 0);
  EXPECT_EQ(outcome((dir / "fifo").string()), "test file is a FIFO, not a regular file");
  EXPECT_EQ(outcome("/dev/null"), "test file is a character device, not a regular file");
  fs::create_symlink("/dev/zero", dir / "zero");  // endless, behind a harmless name
  EXPECT_EQ(outcome((dir / "zero").string()),
            "test file is a character device, not a regular file");
  EXPECT_EQ(outcome(dir.string()), "test file is a folder, not a regular file");
  const int sock = socket(AF_UNIX, SOCK_STREAM, 0);
  sockaddr_un address{};
  address.sun_family = AF_UNIX;
  const std::string socket_path = (dir / "socket").string();
  ASSERT_LT(socket_path.size(), sizeof address.sun_path);
  std::copy(socket_path.begin(), socket_path.end(), address.sun_path);
  ASSERT_EQ(bind(sock, reinterpret_cast<sockaddr*>(&address), sizeof address), 0);
  EXPECT_EQ(outcome(socket_path), "test file is a socket, not a regular file");
  close(sock);
}

TEST_F(InputFileTest, SizeLimit) {
  EXPECT_EQ(outcome(write("big", "01234567890")), "test file is larger than 10 bytes (the limit)");
  // A kernel file claims 0 bytes and gives more: the limit holds while reading.
  struct stat info {};
  ASSERT_EQ(stat("/proc/self/status", &info), 0);
  ASSERT_EQ(info.st_size, 0);
  EXPECT_EQ(outcome("/proc/self/status"), "test file is larger than 10 bytes (the limit)");
  EXPECT_EQ(outcome("/proc/self/status", InputKind{"test file", 1 << 20}).substr(0, 11),
            "read: Name:");
  // The same through the stream the line readers use.
  InputStream in("/proc/self/status", kTen);
  std::string line;
  EXPECT_THROW(std::getline(in, line), InputError);
}

// Read whole, whatever size the file claimed: a kernel file that gives its text to the first
// read only (a sysctl: a second read at an offset gives nothing), one that claims 0 bytes and
// gives several pages, and a file larger than one piece of the reader.
TEST_F(InputFileTest, ReadWholeWhateverSizeItClaimed) {
  const auto whole = [](const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  };
  const InputKind large{"test file", 1 << 24};
  const std::string sysctl = whole("/proc/sys/vm/max_map_count");
  ASSERT_GT(sysctl.size(), 2u);
  EXPECT_EQ(read_input_file("/proc/sys/vm/max_map_count", large), sysctl);
  const std::string maps = read_input_file("/proc/self/maps", large);
  EXPECT_GT(maps.size(), std::size_t(1) << 13);
  EXPECT_EQ(maps.back(), '\n');
  std::string text(3 << 20, 'x');
  for (std::size_t i = 0; i < text.size(); i += 4096) text[i] = char('a' + i / 4096 % 26);
  EXPECT_EQ(read_input_file(write("three_mib", text), large), text);
}

TEST_F(InputFileTest, HashOfWhatIsRead) {
  // SHA-256 of "abc" (FIPS 180-2, appendix B.1).
  EXPECT_EQ(input_sha256(write("abc", "abc"), kTen),
            "sha256:ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  ASSERT_EQ(mkfifo((dir / "fifo").c_str(), 0600), 0);
  EXPECT_THROW(input_sha256((dir / "fifo").string(), kTen), InputError);
  EXPECT_THROW(input_sha256("/proc/self/status", kTen), InputError);
}

}  // namespace
}  // namespace ncube

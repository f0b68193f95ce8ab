// The one gate through which every file the process reads is opened (docs/cli.md, "Input
// files"): the scene or model, every file a model names, the platform, the cost model, an
// activity record. Only regular files are read: a FIFO would block, a device (/dev/zero)
// or a link to one never ends, a folder or a socket is no file. Each kind of file has a
// size limit, held while reading (not only by the size the file claims), so a wrong path
// ends in one clear message (exit 2) rather than a hang or the host's memory exhausted.
#pragma once

#include <cstddef>
#include <istream>
#include <streambuf>
#include <string>
#include <vector>

namespace ncube {

// What a file is read as (named in messages) and the most bytes it may have.
struct InputKind {
  const char* what;
  std::size_t max_bytes;
};

inline constexpr std::size_t kMiB = std::size_t(1) << 20;
inline constexpr InputKind kSceneFile{"scene file", 256 * kMiB};
inline constexpr InputKind kModelFile{"model file", 256 * kMiB};
// A file a model names (an OBJ's material library, a glTF's buffer).
inline constexpr InputKind kModelPart{"model part", 256 * kMiB};
inline constexpr InputKind kPlatformFile{"platform file", 1 * kMiB};
// A SimGrid XML platform names every host and link: far larger than a JSON platform.
inline constexpr InputKind kSimgridPlatformFile{"SimGrid platform file", 64 * kMiB};
inline constexpr InputKind kCostModelFile{"cost model", 1 * kMiB};
inline constexpr InputKind kActivityRecord{"activity record", std::size_t(16) << 30};
// A file of the kernel's (/proc/meminfo): what the host has, for a tool's estimate.
inline constexpr InputKind kKernelFile{"kernel file", 1 * kMiB};
// The kernel's list of a process's memory mappings (/proc/self/maps): about 100 bytes a
// mapping, up to vm.max_map_count (65,530 by default) of them.
inline constexpr InputKind kProcessMapsFile{"process memory map", 64 * kMiB};
// A result file read back by a bench tool (build/embree_floor).
inline constexpr InputKind kResultFile{"result file", 256 * kMiB};

// An open input file. Opening never blocks (O_NONBLOCK: a FIFO is refused, not waited on)
// and checks the descriptor it opened (fstat), not the path again, so no other file can take
// the path's place between the check and the read.
// Throws InputError, each one line naming the file (as `shown`, if given: the name a model
// gives it) after `named_by` (what names it, e.g. "a.obj: names "):
//   "<file>: cannot open <what>: <reason>"       (missing, no permission)
//   "<file>: cannot open <what>: a loop of symbolic links"
//   "<file>: <what> is a FIFO, not a regular file" (also a character device, ...)
//   "<file>: <what> is larger than <n> bytes (the limit)"
//   "<file>: cannot read <what>: <reason>"
class InputFile {
 public:
  InputFile(const std::string& path, const InputKind& kind, const std::string& named_by = "",
            const std::string& shown = "");
  ~InputFile();
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;

  // Up to `n` bytes (fewer only at the end of the file). Throws InputError once the file
  // has given more than the kind's limit, whatever size it claimed.
  std::size_t read(char* buffer, std::size_t n);
  // The rest of the file.
  std::string read_all();
  // The size the file had when opened.
  std::size_t size() const { return size_; }
  // The file actually opened, every link resolved (for checks of where it lies).
  std::string real_path() const;
  // "/proc/self/fd/<n>": the open file, for a library that takes a path and opens it itself.
  std::string descriptor_path() const { return "/proc/self/fd/" + std::to_string(descriptor_); }
  // "<named_by><path>", for messages.
  std::string where() const { return named_by_ + (shown_.empty() ? path_ : shown_); }
  const InputKind& kind() const { return kind_; }

 private:
  std::string path_;
  InputKind kind_;
  std::string named_by_;
  std::string shown_;
  int descriptor_ = -1;
  std::size_t size_ = 0;
  std::size_t given_ = 0;
};

// The whole of `path` (InputFile's checks and messages).
std::string read_input_file(const std::string& path, const InputKind& kind,
                            const std::string& named_by = "");

// "sha256:<64 hex digits>" of the file's bytes, read through the same checks and limit.
std::string input_sha256(const std::string& path, const InputKind& kind,
                         const std::string& named_by = "");

// An input file as a std::istream, for the readers that parse line by line. A file that
// goes past its limit or cannot be read throws InputError out of the read (badbit).
class InputStream : public std::istream {
 public:
  InputStream(const std::string& path, const InputKind& kind, const std::string& named_by = "");
  const InputFile& file() const { return buffer_.file; }

 private:
  struct Buffer : std::streambuf {
    Buffer(const std::string& path, const InputKind& kind, const std::string& named_by)
        : file(path, kind, named_by) {}
    int_type underflow() override;
    InputFile file;
    std::vector<char> bytes = std::vector<char>(1 << 16);
  };
  Buffer buffer_;
};

}  // namespace ncube

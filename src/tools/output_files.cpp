#include "tools/output_files.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <system_error>

#include "util/input_error.h"

namespace ncube {
namespace {

namespace fs = std::filesystem;

// The file a path names, for comparing paths: symbolic links and "." or ".." resolved as
// far as the path exists.
fs::path identity(const std::string& path) {
  std::error_code error;
  const fs::path resolved = fs::weakly_canonical(fs::absolute(path, error), error);
  return error ? fs::absolute(path) : resolved;
}

// Permission bits of a new file under the process's umask (mkstemp creates 0600).
mode_t new_file_mode() {
  const mode_t mask = umask(0);
  umask(mask);
  return 0666 & ~mask;
}

// At most this many symbolic links are followed from an output path (Linux's own limit).
constexpr int kMaxLinks = 40;

// `path` with the symbolic links of its last component followed: the path that is written.
// A dangling link gives the path of its missing target (which is then created).
std::string follow_links(const std::string& path, const std::string& where) {
  fs::path current(path);
  for (int links = 0; links <= kMaxLinks; ++links) {
    struct stat info {};
    if (lstat(current.c_str(), &info) != 0 || !S_ISLNK(info.st_mode)) return current.string();
    std::error_code error;
    const fs::path target = fs::read_symlink(current, error);
    if (error) throw InputError(where + "cannot read the link " + current.string());
    current = target.is_absolute() ? target : current.parent_path() / target;
  }
  throw InputError(where + "more than " + std::to_string(kMaxLinks) + " symbolic links");
}

// Whether `path` is where the process's standard output goes ("/dev/stdout", or the file
// or pipe it was redirected to, by any name).
bool is_standard_output(const std::string& path) {
  if (path == "-") return true;
  struct stat named {}, out {};
  return stat(path.c_str(), &named) == 0 && fstat(STDOUT_FILENO, &out) == 0 &&
         named.st_dev == out.st_dev && named.st_ino == out.st_ino;
}

// Writes all of `content` to `descriptor`; false (errno set) on an error.
bool write_all(int descriptor, const std::string& content) {
  const char* data = content.data();
  std::size_t left = content.size();
  while (left > 0) {
    const ssize_t done = ::write(descriptor, data, left);
    if (done < 0 && errno == EINTR) continue;
    if (done <= 0) {
      if (done == 0) errno = EIO;
      return false;
    }
    data += done;
    left -= std::size_t(done);
  }
  return true;
}

}  // namespace

OutputFiles::OutputFiles(const std::vector<Output>& outputs, const std::vector<std::string>& inputs) {
  try {
    open(outputs, inputs);
  } catch (...) {
    remove_temporaries();  // a constructor that throws gets no destructor call
    throw;
  }
}

void OutputFiles::open(const std::vector<Output>& outputs, const std::vector<std::string>& inputs) {
  std::vector<fs::path> taken;
  for (const std::string& input : inputs) taken.push_back(identity(input));
  bool standard_output_taken = false;
  for (const Output& output : outputs) {
    if (output.path.empty()) continue;
    const std::string where = output.option + " " + output.path + ": ";
    Pending pending;
    pending.option = output.option;
    pending.path = output.path;
    if (is_standard_output(output.path)) {
      if (standard_output_taken) throw InputError(where + "standard output is also another output");
      standard_output_taken = true;
      pending.kind = Kind::kStandardOutput;
      pending_.push_back(pending);
      continue;
    }
    if (!fs::path(output.path).has_filename())
      throw InputError(where + "names a folder, not a file");
    pending.target = follow_links(output.path, where);
    struct stat info {};
    const bool exists = stat(pending.target.c_str(), &info) == 0;
    if (exists && (S_ISCHR(info.st_mode) || S_ISFIFO(info.st_mode))) {
      // Written where it points; two outputs may well share /dev/null.
      pending.kind = Kind::kStream;
      pending_.push_back(pending);
      continue;
    }
    if (exists && !S_ISREG(info.st_mode))
      throw OutputError(where + "cannot be written: it is " +
                        (S_ISDIR(info.st_mode)    ? "a folder"
                         : S_ISSOCK(info.st_mode) ? "a socket"
                         : S_ISBLK(info.st_mode)  ? "a block device"
                                                  : "not a file"));
    const fs::path id = identity(pending.target);
    for (std::size_t k = 0; k < taken.size(); ++k)
      if (id == taken[k])
        throw InputError(where + (k < inputs.size() ? "is the input file " + inputs[k]
                                                    : "is also another output"));
    taken.push_back(id);
    open_file(pending, where);
  }
}

// A new or regular file: a temporary file in the target's folder, renamed onto it at commit.
void OutputFiles::open_file(Pending& pending, const std::string& where) {
  const fs::path target(pending.target);
  const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::error_code error;
  if (!fs::is_directory(folder, error))
    throw InputError(where + "folder " + folder.string() +
                     (fs::exists(folder, error) ? " is not a folder" : " does not exist"));
  pending.temporary = pending.target + ".partial-XXXXXX";
  pending.descriptor = mkstemp(pending.temporary.data());
  if (pending.descriptor < 0) {
    pending.temporary.clear();
    throw InputError(where + "cannot create a file in folder " + folder.string() + ": " +
                     std::strerror(errno));
  }
  fchmod(pending.descriptor, new_file_mode());
  pending_.push_back(pending);
}

bool OutputFiles::uses_standard_output() const {
  for (const Pending& p : pending_)
    if (p.kind == Kind::kStandardOutput) return true;
  return false;
}

OutputFiles::~OutputFiles() { remove_temporaries(); }

void OutputFiles::remove_temporaries() {
  for (Pending& p : pending_) {
    if (p.descriptor >= 0) close(p.descriptor);
    p.descriptor = -1;
    if (!p.temporary.empty()) std::remove(p.temporary.c_str());
    p.temporary.clear();
  }
}

void OutputFiles::write(const std::string& option, const std::string& content) {
  for (Pending& p : pending_) {
    if (p.option != option) continue;
    if (p.kind != Kind::kFile) {
      p.content = content;
      p.written = true;
      return;
    }
    if (!write_all(p.descriptor, content))
      throw OutputError(option + " " + p.path + ": cannot write: " + std::strerror(errno));
    const int descriptor = p.descriptor;
    p.descriptor = -1;
    if (close(descriptor) != 0)
      throw OutputError(option + " " + p.path + ": cannot write: " + std::strerror(errno));
    p.written = true;
    return;
  }
}

// A device, a FIFO or standard output: opened only now (a FIFO waits for its reader), never
// created, truncated or replaced.
void OutputFiles::stream(const Pending& p) const {
  // A reader that went away is a write error (EPIPE: exit 5), not a silent death by SIGPIPE.
  std::signal(SIGPIPE, SIG_IGN);
  const std::string where = p.option + " " + p.path + ": cannot write: ";
  if (p.kind == Kind::kStandardOutput) {
    std::fflush(stdout);
    if (!write_all(STDOUT_FILENO, p.content)) throw OutputError(where + std::strerror(errno));
    return;
  }
  const int descriptor = ::open(p.target.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC);
  if (descriptor < 0) throw OutputError(where + std::strerror(errno));
  const bool ok = write_all(descriptor, p.content);
  const int saved = errno;
  if (close(descriptor) != 0 && ok) throw OutputError(where + std::strerror(errno));
  if (!ok) throw OutputError(where + std::strerror(saved));
}

void OutputFiles::commit() {
  // The streams first: a full device or a closed pipe then leaves every file unchanged.
  for (const Pending& p : pending_)
    if (p.written && p.kind != Kind::kFile) stream(p);
  for (Pending& p : pending_) {
    if (!p.written || p.kind != Kind::kFile) continue;
    if (std::rename(p.temporary.c_str(), p.target.c_str()) != 0)
      throw OutputError(p.option + " " + p.path + ": cannot rename the written file onto it: " +
                        std::strerror(errno));
    p.temporary.clear();  // renamed: nothing to remove
  }
}

}  // namespace ncube

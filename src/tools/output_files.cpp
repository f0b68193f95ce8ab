#include "tools/output_files.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <memory>
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

}  // namespace

OutputFiles::OutputFiles(const std::vector<Output>& outputs, const std::vector<std::string>& inputs) {
  open(outputs, inputs);  // a throw destroys the temporary files made so far
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
      pending.temporary = std::make_unique<TemporaryFile>(TemporaryFile::anywhere());
      pending_.push_back(std::move(pending));
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
      pending.temporary = std::make_unique<TemporaryFile>(TemporaryFile::anywhere());
      pending_.push_back(std::move(pending));
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

// A new or regular file: a temporary file in the target's folder, named and renamed onto it
// at commit.
void OutputFiles::open_file(Pending& pending, const std::string& where) {
  const fs::path target(pending.target);
  const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::error_code error;
  if (!fs::is_directory(folder, error))
    throw InputError(where + "folder " + folder.string() +
                     (fs::exists(folder, error) ? " is not a folder" : " does not exist"));
  try {
    pending.temporary = std::make_unique<TemporaryFile>(
        TemporaryFile::in_folder(folder.string(), target.filename().string()));
  } catch (const std::system_error& e) {
    throw InputError(where + "cannot create a file in folder " + folder.string() + ": " +
                     std::strerror(e.code().value()));
  }
  pending_.push_back(std::move(pending));
}

bool OutputFiles::uses_standard_output() const {
  for (const Pending& p : pending_)
    if (p.kind == Kind::kStandardOutput) return true;
  return false;
}

OutputFiles::Pending* OutputFiles::find(const std::string& option) {
  for (Pending& p : pending_)
    if (p.option == option) return &p;
  return nullptr;
}

void OutputFiles::write(const std::string& option, std::string_view content) {
  Pending* p = find(option);
  if (!p) return;
  p->written = true;
  if (!p->temporary->append(content))
    throw OutputError(option + " " + p->path + ": cannot write: " + std::strerror(errno));
}

std::string OutputFiles::writer_path(const std::string& option) {
  Pending* p = find(option);
  if (!p) return "";
  p->written = true;
  return p->temporary->writer_path();
}

// A device, a FIFO or standard output: opened only now (a FIFO waits for its reader), never
// created, truncated or replaced.
void OutputFiles::stream(const Pending& p) const {
  // A reader that went away is a write error (EPIPE: exit 5), not a silent death by SIGPIPE.
  std::signal(SIGPIPE, SIG_IGN);
  const std::string where = p.option + " " + p.path + ": cannot write: ";
  if (p.kind == Kind::kStandardOutput) {
    std::fflush(stdout);
    if (!p.temporary->copy_to(STDOUT_FILENO)) throw OutputError(where + std::strerror(errno));
    return;
  }
  const int descriptor = ::open(p.target.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC);
  if (descriptor < 0) throw OutputError(where + std::strerror(errno));
  const bool ok = p.temporary->copy_to(descriptor);
  const int saved = errno;
  if (close(descriptor) != 0 && ok) throw OutputError(where + std::strerror(errno));
  if (!ok) throw OutputError(where + std::strerror(saved));
}

void OutputFiles::commit() {
  std::fflush(nullptr);  // what other writers (SimGrid's log appenders) still buffer
  // The streams first: a full device or a closed pipe then leaves every file unchanged.
  for (const Pending& p : pending_)
    if (p.written && p.kind != Kind::kFile) stream(p);
  // Every file gets its name beside its target before any is renamed: a failure here (or a
  // target that became a folder during the run) leaves every target unchanged.
  const auto failed = [](const Pending& p, const char* what) {
    return OutputError(p.option + " " + p.path + ": " + what + ": " + std::strerror(errno));
  };
  for (Pending& p : pending_) {
    if (!p.written || p.kind != Kind::kFile) continue;
    if (!p.temporary->name_beside(p.target)) throw failed(p, "cannot write");
    struct stat info {};
    if (lstat(p.target.c_str(), &info) == 0 && S_ISDIR(info.st_mode)) {
      errno = EISDIR;
      throw failed(p, "cannot rename the written file onto it");
    }
  }
  for (Pending& p : pending_)
    if (p.written && p.kind == Kind::kFile && !p.temporary->keep_as(p.target))
      throw failed(p, "cannot rename the written file onto it");
}

std::vector<OutputFiles::Output> OutputFiles::written() const {
  std::vector<Output> done;
  for (const Pending& p : pending_)
    if (p.written) done.push_back({p.option, p.path});
  return done;
}

}  // namespace ncube

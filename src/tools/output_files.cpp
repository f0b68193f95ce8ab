#include "tools/output_files.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
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
  for (const Output& output : outputs) {
    if (output.path.empty()) continue;
    const std::string where = output.option + " " + output.path + ": ";
    const fs::path path(output.path);
    std::error_code error;
    if (!path.has_filename() || fs::is_directory(path, error))
      throw InputError(where + "names a folder, not a file");
    const fs::path folder = path.has_parent_path() ? path.parent_path() : fs::path(".");
    if (!fs::is_directory(folder, error))
      throw InputError(where + "folder " + folder.string() +
                       (fs::exists(folder, error) ? " is not a folder" : " does not exist"));
    const fs::path id = identity(output.path);
    for (std::size_t k = 0; k < taken.size(); ++k)
      if (id == taken[k])
        throw InputError(where + (k < inputs.size() ? "is the input file " + inputs[k]
                                                    : "is also another output"));
    taken.push_back(id);
    Pending pending{output.option, output.path, output.path + ".partial-XXXXXX"};
    pending.descriptor = mkstemp(pending.temporary.data());
    if (pending.descriptor < 0)
      throw InputError(where + "cannot create a file in folder " + folder.string() + ": " +
                       std::strerror(errno));
    fchmod(pending.descriptor, new_file_mode());
    pending_.push_back(pending);
  }
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
    const char* data = content.data();
    std::size_t left = content.size();
    while (left > 0) {
      const ssize_t done = ::write(p.descriptor, data, left);
      if (done < 0 && errno == EINTR) continue;
      if (done <= 0)
        throw OutputError(option + " " + p.path + ": cannot write: " +
                          std::strerror(done < 0 ? errno : EIO));
      data += done;
      left -= std::size_t(done);
    }
    const int descriptor = p.descriptor;
    p.descriptor = -1;
    if (close(descriptor) != 0)
      throw OutputError(option + " " + p.path + ": cannot write: " + std::strerror(errno));
    p.written = true;
    return;
  }
}

void OutputFiles::commit() {
  for (Pending& p : pending_) {
    if (!p.written) continue;
    if (std::rename(p.temporary.c_str(), p.path.c_str()) != 0)
      throw OutputError(p.option + " " + p.path + ": cannot rename the written file onto it: " +
                        std::strerror(errno));
    p.temporary.clear();  // renamed: nothing to remove
  }
}

}  // namespace ncube

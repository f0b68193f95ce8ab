#include "tools/temporary_file.h"

#include <fcntl.h>
#include <sys/random.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <system_error>

namespace ncube {
namespace {

// The names of temporary files that exist now, for the exit and signal handlers: fixed
// slots, so that a handler reads them without allocating or locking.
constexpr int kSlots = 64;
std::atomic<char*> named_files[kSlots];

void remove_named_files() {
  for (std::atomic<char*>& slot : named_files)
    if (const char* name = slot.load()) unlink(name);
}

extern "C" void remove_named_files_at_exit() { remove_named_files(); }

// SA_RESETHAND: the signal's default action is back, so raising it again (blocked until the
// handler returns) ends the process as the signal would have.
extern "C" void remove_named_files_on_signal(int signal_number) {
  remove_named_files();
  raise(signal_number);
}

// Handlers for every signal whose default ends the process, where nobody set one (SimGrid's
// own SIGINT handler is taken back: src/machine/simgrid_session.cpp).
void install_handlers() {
  static bool installed = false;
  if (installed) return;
  installed = true;
  std::atexit(remove_named_files_at_exit);
  for (int signal_number : {SIGHUP, SIGINT, SIGQUIT, SIGTERM, SIGSEGV, SIGBUS, SIGABRT, SIGFPE,
                            SIGILL, SIGXCPU, SIGXFSZ, SIGALRM, SIGUSR1, SIGUSR2}) {
    struct sigaction now {};
    if (sigaction(signal_number, nullptr, &now) != 0) continue;
    if ((now.sa_flags & SA_SIGINFO) || now.sa_handler != SIG_DFL) continue;
    struct sigaction action {};
    action.sa_handler = remove_named_files_on_signal;
    action.sa_flags = SA_RESETHAND;
    sigemptyset(&action.sa_mask);
    sigaction(signal_number, &action, nullptr);
  }
}

void register_name(const std::string& name) {
  install_handlers();
  char* copy = strdup(name.c_str());
  for (std::atomic<char*>& slot : named_files) {
    char* empty = nullptr;
    if (slot.compare_exchange_strong(empty, copy)) return;
  }
  std::free(copy);  // more than kSlots at once: removed by the destructor only
}

void unregister_name(const std::string& name) {
  for (std::atomic<char*>& slot : named_files) {
    char* held = slot.load();
    if (held && name == held && slot.compare_exchange_strong(held, nullptr)) {
      std::free(held);
      return;
    }
  }
}

// Permission bits of a new file under the process's umask (mkostemp creates 0600).
mode_t new_file_mode() {
  const mode_t mask = umask(0);
  umask(mask);
  return 0666 & ~mask;
}

std::string descriptor_path(int descriptor) { return "/proc/self/fd/" + std::to_string(descriptor); }

// Twelve unpredictable characters for a file name.
std::string random_suffix() {
  static const char kAlphabet[] = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-";
  unsigned char bytes[12];
  if (getrandom(bytes, sizeof bytes, 0) != ssize_t(sizeof bytes))
    throw std::system_error(errno, std::generic_category(), "getrandom");
  std::string suffix;
  for (unsigned char b : bytes) suffix += kAlphabet[b % 64];
  return suffix;
}

}  // namespace

TemporaryFile TemporaryFile::in_folder(const std::string& folder, const std::string& stem,
                                       bool anonymous) {
  TemporaryFile file;
  file.folder_ = folder;
  if (anonymous) {
    // An inode with no name; linked at keep_as through /proc/self/fd (so /proc must be there).
    file.descriptor_ = open(folder.c_str(), O_TMPFILE | O_RDWR | O_CLOEXEC, 0666);
    if (file.descriptor_ >= 0 && access(descriptor_path(file.descriptor_).c_str(), F_OK) == 0)
      return file;
    const int why = errno;
    if (file.descriptor_ >= 0) close(file.descriptor_);
    file.descriptor_ = -1;
    // Only a file system without O_TMPFILE falls back to a name; anything else is an error.
    if (why != EOPNOTSUPP && why != EISDIR && why != EINVAL && why != ENOENT)
      throw std::system_error(why, std::generic_category(), folder);
  }
  std::string name = folder + "/" + stem + ".partial-XXXXXX";
  const int descriptor = mkostemp(name.data(), O_CLOEXEC);
  if (descriptor < 0) throw std::system_error(errno, std::generic_category(), folder);
  register_name(name);
  fchmod(descriptor, new_file_mode());
  file.descriptor_ = descriptor;
  file.name_ = name;
  return file;
}

TemporaryFile TemporaryFile::anywhere() {
  const char* tmpdir = std::getenv("TMPDIR");
  const std::string folder = tmpdir && *tmpdir ? tmpdir : "/tmp";
  TemporaryFile file;
  file.descriptor_ = open(folder.c_str(), O_TMPFILE | O_RDWR | O_CLOEXEC, 0600);
  if (file.descriptor_ >= 0) return file;
  std::string name = folder + "/ncube-XXXXXX";
  file.descriptor_ = mkostemp(name.data(), O_CLOEXEC);
  if (file.descriptor_ < 0) throw std::system_error(errno, std::generic_category(), folder);
  unlink(name.c_str());  // no name from here on; /proc/self/fd still opens it
  return file;
}

TemporaryFile::TemporaryFile(TemporaryFile&& other) noexcept { *this = std::move(other); }

TemporaryFile& TemporaryFile::operator=(TemporaryFile&& other) noexcept {
  if (this != &other) {
    release();
    descriptor_ = other.descriptor_;
    folder_ = std::move(other.folder_);
    name_ = std::move(other.name_);
    other.descriptor_ = -1;
    other.name_.clear();
  }
  return *this;
}

TemporaryFile::~TemporaryFile() { release(); }

void TemporaryFile::release() {
  if (descriptor_ >= 0) close(descriptor_);
  descriptor_ = -1;
  if (!name_.empty()) {
    unlink(name_.c_str());
    unregister_name(name_);
  }
  name_.clear();
}

bool TemporaryFile::append(std::string_view bytes) {
  const char* data = bytes.data();
  std::size_t left = bytes.size();
  while (left > 0) {
    const ssize_t done = ::write(descriptor_, data, left);
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

std::string TemporaryFile::writer_path() const {
  return name_.empty() ? descriptor_path(descriptor_) : name_;
}

bool TemporaryFile::name_beside(const std::string& target) {
  if (!name_.empty()) return true;
  // A fresh name beside the target, registered before it exists.
  const std::string stem = target.substr(target.find_last_of('/') + 1);
  for (int attempt = 0;; ++attempt) {
    const std::string name = folder_ + "/" + stem + ".partial-" + random_suffix();
    register_name(name);
    if (linkat(AT_FDCWD, descriptor_path(descriptor_).c_str(), AT_FDCWD, name.c_str(),
               AT_SYMLINK_FOLLOW) == 0) {
      name_ = name;
      return true;
    }
    const int why = errno;
    unregister_name(name);
    errno = why;
    if (why != EEXIST || attempt == 100) return false;
  }
}

bool TemporaryFile::keep_as(const std::string& target) {
  if (!name_beside(target)) return false;
  const int descriptor = descriptor_;
  descriptor_ = -1;
  if (close(descriptor) != 0) return false;  // a late write error (NFS): the name goes
  if (std::rename(name_.c_str(), target.c_str()) != 0) return false;
  unregister_name(name_);
  name_.clear();
  return true;
}

bool TemporaryFile::copy_to(int descriptor) const {
  char buffer[1 << 16];
  for (off_t offset = 0;;) {
    const ssize_t got = pread(descriptor_, buffer, sizeof buffer, offset);
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) return false;
    if (got == 0) return true;
    offset += got;
    for (ssize_t put = 0; put < got;) {
      const ssize_t done = ::write(descriptor, buffer + put, std::size_t(got - put));
      if (done < 0 && errno == EINTR) continue;
      if (done <= 0) {
        if (done == 0) errno = EIO;
        return false;
      }
      put += done;
    }
  }
}

}  // namespace ncube

#include "util/input_file.h"

#include <fcntl.h>
#include <openssl/evp.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

#include "util/input_error.h"

namespace ncube {
namespace {

const char* file_type(mode_t mode) {
  if (S_ISDIR(mode)) return "a folder";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a file";
}

}  // namespace

InputFile::InputFile(const std::string& path, const InputKind& kind, const std::string& named_by,
                     const std::string& shown)
    : path_(path), kind_(kind), named_by_(named_by), shown_(shown) {
  // O_NONBLOCK: opening a FIFO for reading would wait for a writer. O_NOCTTY: a terminal
  // named as input does not become the process's controlling terminal.
  descriptor_ = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
  if (descriptor_ < 0) {
    const int error = errno;
    struct stat named {};
    // A socket cannot be opened at all (ENXIO): say what it is rather than "no such device".
    if (error == ENXIO && ::stat(path.c_str(), &named) == 0 && !S_ISREG(named.st_mode))
      throw InputError(where() + ": " + kind.what + " is " + file_type(named.st_mode) +
                       ", not a regular file");
    throw InputError(where() + ": cannot open " + kind.what + ": " +
                     (error == ELOOP ? std::string("a loop of symbolic links")
                                     : std::string(std::strerror(error))));
  }
  struct stat info {};
  if (::fstat(descriptor_, &info) != 0 || !S_ISREG(info.st_mode)) {
    const std::string type = file_type(info.st_mode);
    ::close(descriptor_);
    throw InputError(where() + ": " + kind.what + " is " + type + ", not a regular file");
  }
  size_ = std::size_t(info.st_size);
  if (size_ > kind.max_bytes) {
    ::close(descriptor_);
    throw InputError(where() + ": " + kind.what + " is larger than " +
                     std::to_string(kind.max_bytes) + " bytes (the limit)");
  }
}

InputFile::~InputFile() { ::close(descriptor_); }

std::size_t InputFile::read(char* buffer, std::size_t n) {
  std::size_t got = 0;
  while (got < n) {
    const ssize_t r = ::read(descriptor_, buffer + got, n - got);
    if (r < 0 && errno == EINTR) continue;
    if (r < 0)
      throw InputError(where() + ": cannot read " + kind_.what + ": " + std::strerror(errno));
    if (r == 0) break;
    got += std::size_t(r);
  }
  given_ += got;
  // A file may give more than it claimed (a growing file, a kernel's file of size 0).
  if (given_ > kind_.max_bytes)
    throw InputError(where() + ": " + kind_.what + " is larger than " +
                     std::to_string(kind_.max_bytes) + " bytes (the limit)");
  return got;
}

std::string InputFile::read_all() {
  // Read in pieces, joined once; at most one byte past the limit is asked for. The first piece
  // is the size the file had when opened and a byte more (which finds its end, or that it
  // grew), at least 64 KiB (a kernel's file claims size 0 and gives its text to the first read
  // only: /proc/sys/vm/max_map_count), not a zeroed MiB for a file of a few hundred bytes;
  // pieces of 1 MiB follow only for what a file gives beyond that.
  std::vector<std::string> pieces;
  std::size_t total = 0, want = std::max<std::size_t>(size_ + 1, 1 << 16);
  for (;;) {
    std::string piece(std::min<std::size_t>(want, kind_.max_bytes + 1 - given_), '\0');
    const std::size_t asked = piece.size();
    const std::size_t got = read(piece.data(), asked);
    piece.resize(got);
    total += got;
    pieces.push_back(std::move(piece));
    if (got < asked) break;  // read() gives fewer than asked only at the end
    want = 1 << 20;
  }
  if (pieces.size() == 1) return std::move(pieces.front());
  std::string text;
  text.reserve(total);
  for (const std::string& piece : pieces) text += piece;
  return text;
}

std::string InputFile::real_path() const {
  std::vector<char> target(4096);
  const std::string link = descriptor_path();
  const ssize_t n = ::readlink(link.c_str(), target.data(), target.size());
  if (n < 0 || std::size_t(n) >= target.size())
    throw InputError(where() + ": cannot tell where the " + kind_.what + " lies");
  return std::string(target.data(), std::size_t(n));
}

std::string read_input_file(const std::string& path, const InputKind& kind,
                            const std::string& named_by) {
  return InputFile(path, kind, named_by).read_all();
}

std::string input_sha256(const std::string& path, const InputKind& kind,
                         const std::string& named_by) {
  InputFile file(path, kind, named_by);
  std::unique_ptr<EVP_MD_CTX, decltype(&EVP_MD_CTX_free)> context(EVP_MD_CTX_new(),
                                                                  EVP_MD_CTX_free);
  EVP_DigestInit_ex(context.get(), EVP_sha256(), nullptr);
  std::vector<char> buffer(1 << 16);
  for (std::size_t got; (got = file.read(buffer.data(), buffer.size())) > 0;)
    EVP_DigestUpdate(context.get(), buffer.data(), got);
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int length = 0;
  EVP_DigestFinal_ex(context.get(), digest, &length);
  std::string text = "sha256:";
  char hex[3];
  for (unsigned int k = 0; k < length; ++k) {
    std::snprintf(hex, sizeof hex, "%02x", digest[k]);
    text += hex;
  }
  return text;
}

InputStream::InputStream(const std::string& path, const InputKind& kind,
                         const std::string& named_by)
    : std::istream(nullptr), buffer_(path, kind, named_by) {
  rdbuf(&buffer_);
  exceptions(std::ios::badbit);  // the InputError of a failed read reaches the caller
}

InputStream::Buffer::int_type InputStream::Buffer::underflow() {
  const std::size_t got = file.read(bytes.data(), bytes.size());
  if (got == 0) return traits_type::eof();
  setg(bytes.data(), bytes.data(), bytes.data() + got);
  return traits_type::to_int_type(bytes[0]);
}

}  // namespace ncube

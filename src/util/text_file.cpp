#include "util/text_file.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <vector>

#include "util/input_error.h"

namespace ncube {

std::string read_text_file(const std::string& path, std::size_t max_bytes, const std::string& what) {
  // C stdio rather than ifstream: it reports why a file cannot be opened or read (errno),
  // including reading a directory.
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (!file) throw InputError(path + ": cannot open " + what + ": " + std::strerror(errno));
  // Read in pieces and joined once: a string grown by doubling would take up to four times
  // the limit in address space on an endless file (/dev/zero), as malloc may keep what it
  // freed. Reads at most one byte past the limit: enough to know the file is too large.
  std::vector<std::string> pieces;
  std::size_t size = 0, got = 0;
  do {
    std::string piece(std::min<std::size_t>(1 << 20, max_bytes + 1 - size), '\0');
    got = std::fread(piece.data(), 1, piece.size(), file);
    piece.resize(got);
    size += got;
    pieces.push_back(std::move(piece));
  } while (got > 0 && size <= max_bytes);
  const bool failed = std::ferror(file);
  const int error = errno;
  std::fclose(file);
  if (failed) throw InputError(path + ": cannot read " + what + ": " + std::strerror(error));
  if (size > max_bytes)
    throw InputError(path + ": " + what + " is larger than " + std::to_string(max_bytes) +
                     " bytes (the limit)");
  std::string text;
  text.reserve(size);
  for (const std::string& piece : pieces) text += piece;
  return text;
}

}  // namespace ncube

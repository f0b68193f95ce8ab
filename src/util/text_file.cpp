#include "util/text_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "util/input_error.h"

namespace ncube {

std::string read_text_file(const std::string& path, std::size_t max_bytes, const std::string& what) {
  // C stdio rather than ifstream: it reports why a file cannot be opened or read (errno),
  // including reading a directory.
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (!file) throw InputError(path + ": cannot open " + what + ": " + std::strerror(errno));
  std::string text;
  char buffer[1 << 16];
  std::size_t got;
  // Reads at most one byte past the limit: enough to know the file is too large, and it
  // stops on endless files (/dev/zero) too.
  while (text.size() <= max_bytes &&
         (got = std::fread(buffer, 1, std::min(sizeof buffer, max_bytes + 1 - text.size()), file)) > 0)
    text.append(buffer, got);
  const bool failed = std::ferror(file);
  const int error = errno;
  std::fclose(file);
  if (failed) throw InputError(path + ": cannot read " + what + ": " + std::strerror(error));
  if (text.size() > max_bytes)
    throw InputError(path + ": " + what + " is larger than " + std::to_string(max_bytes) +
                     " bytes (the limit)");
  return text;
}

}  // namespace ncube

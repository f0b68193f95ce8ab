// Content hashes of input files, so that a result file names exactly what it was computed
// from (docs/result-format.md, "provenance") and a sweep can tell a stale result.
#pragma once

#include <string>

namespace ncube {

// "sha256:<64 hex digits>" of the file's bytes. Throws InputError naming the file when it
// cannot be read.
std::string file_sha256(const std::string& path);

}  // namespace ncube

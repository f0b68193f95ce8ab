// Reading a whole input file into memory, with a size limit so that a wrong path (a device
// such as /dev/zero, a huge unrelated file) ends in a clear message instead of exhausting
// the host's memory.
#pragma once

#include <cstddef>
#include <string>

namespace ncube {

// The contents of `path`. Throws InputError "<path>: cannot open <what>: <reason>",
// "<path>: cannot read <what>: <reason>" or "<path>: <what> is larger than <max_bytes>
// bytes (the limit)".
std::string read_text_file(const std::string& path, std::size_t max_bytes, const std::string& what);

}  // namespace ncube

// The host's threads for one compute step of a node program (a radiosity processor's
// receivers, a visibility processor's block of points). Host threads only share out work
// whose items are independent, so no answer, count or result depends on how many there are.
// Contract (host side): no answer, count or result depends on the number of threads
// (tests/host_threads_test.sh).
#pragma once

#include "host/host_side.h"

#include <cstddef>
#include <functional>

namespace ncube {

// The number of threads `--threads N` asks for: N, or every core of the host for N <= 0.
int resolve_host_threads(int requested);

// Runs body(begin, end) over disjoint chunks covering [0, count), on up to `threads` host
// threads (resolved as above; 1 runs inline on the caller). Chunks hold at least `grain` items.
// The caller must not rely on the order of chunks.
void parallel_chunks(int threads, std::size_t count, std::size_t grain,
                     const std::function<void(std::size_t begin, std::size_t end)>& body);

}  // namespace ncube

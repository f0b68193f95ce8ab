#include "host/host_threads.h"

#include <omp.h>

#include <algorithm>
#include <thread>

namespace ncube {

int resolve_host_threads(int requested) {
  if (requested > 0) return requested;
  const unsigned cores = std::thread::hardware_concurrency();
  return cores > 0 ? int(cores) : 1;
}

void parallel_chunks(int threads, std::size_t count, std::size_t grain,
                     const std::function<void(std::size_t begin, std::size_t end)>& body) {
  threads = resolve_host_threads(threads);
  if (grain < 1) grain = 1;
  if (threads == 1 || count <= grain) {
    if (count > 0) body(0, count);
    return;
  }
  // OpenMP (GCC's libgomp), not TBB: the node programs run on SimGrid's actor stacks, and
  // TBB then runs a parallel loop on the calling thread alone (measured).
  const long chunks = long((count + grain - 1) / grain);
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
  for (long chunk = 0; chunk < chunks; ++chunk) {
    const std::size_t begin = std::size_t(chunk) * grain;
    body(begin, std::min(count, begin + grain));
  }
}

}  // namespace ncube

#include "host/host_threads.h"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <exception>
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
  // An exception must not leave an OpenMP region (the process would end in std::terminate,
  // not the documented exit 6 for the host out of memory): the first is kept, the chunks not
  // yet started are skipped, and it is rethrown on the caller's thread.
  const long chunks = long((count + grain - 1) / grain);
  std::exception_ptr failure;
  std::atomic<bool> failed{false};
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
  for (long chunk = 0; chunk < chunks; ++chunk) {
    if (failed.load(std::memory_order_relaxed)) continue;
    const std::size_t begin = std::size_t(chunk) * grain;
    try {
      body(begin, std::min(count, begin + grain));
    } catch (...) {
#pragma omp critical(ncube_parallel_chunks_failure)
      if (!failure) failure = std::current_exception();
      failed.store(true, std::memory_order_relaxed);
    }
  }
  if (failure) std::rethrow_exception(failure);
}

}  // namespace ncube

// parallel_chunks (src/host/host_threads.h) carries an exception out of its OpenMP region to
// the caller: std::bad_alloc in one chunk on a worker thread reaches the node program (and so
// main's exit 6) instead of std::terminate ending the process.
#include "host/host_threads.h"

#include <gtest/gtest.h>

#include <atomic>
#include <new>
#include <stdexcept>

namespace ncube {
namespace {

TEST(HostThreads, ExceptionInAChunkReachesTheCaller) {
  std::atomic<long> done{0};
  // Chunks of 1 over 64 items on 4 threads: item 37 fails, wherever it runs.
  EXPECT_THROW(parallel_chunks(4, 64, 1,
                               [&](std::size_t begin, std::size_t end) {
                                 for (std::size_t k = begin; k < end; ++k) {
                                   if (k == 37) throw std::bad_alloc();
                                   ++done;
                                 }
                               }),
               std::bad_alloc);
  EXPECT_LT(done.load(), 64);
  // The first kept is what is rethrown: one kind of exception only here.
  EXPECT_THROW(parallel_chunks(2, 8, 1, [](std::size_t, std::size_t) { throw std::runtime_error("x"); }),
               std::runtime_error);
  // Without an exception every item is done once.
  std::atomic<long> sum{0};
  parallel_chunks(4, 1000, 7, [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) sum += long(k);
  });
  EXPECT_EQ(sum.load(), 999L * 1000 / 2);
}

}  // namespace
}  // namespace ncube

#include "host/threaded_occluders.h"

#include <mutex>

#include "host/host_threads.h"

namespace ncube {

void ThreadedOccluders::unblocked_parts(const PointBlock& block, const Shooter& shooter,
                                        PartMask* masks, WorkCounts& counts) const {
  std::mutex merge;
  parallel_chunks(threads_, block.count, 8, [&](std::size_t begin, std::size_t end) {
    WorkCounts local;
    set_->unblocked_parts(block.part(begin, end), shooter, masks + begin, local);
    const std::lock_guard<std::mutex> lock(merge);
    counts += local;  // integer sums: the same whatever the order
  });
}

}  // namespace ncube

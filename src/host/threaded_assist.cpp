#include "host/threaded_assist.h"

#include "host/host_threads.h"

namespace ncube {

void ThreadedAssist::share_out(std::size_t count, std::size_t grain,
                               const std::function<void(std::size_t, std::size_t)>& body) const {
  parallel_chunks(threads_, count, grain, body);
}

}  // namespace ncube

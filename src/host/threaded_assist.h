// The host's simplest help (radiosity/host_assist.h): the independent items of one compute
// step (a radiosity processor's receivers' form factors) shared out over host threads.
//
// Contract (host side): it changes no answer and no count; each item is computed by the same
// function on the same inputs whichever thread takes it, and the results are used in item
// order (tests/host_threads_test.sh: result files equal for 1, 2 and 3 threads).
#pragma once

#include "host/host_side.h"
#include "radiosity/host_assist.h"

namespace ncube {

class ThreadedAssist : public HostAssist {
 public:
  explicit ThreadedAssist(int threads) : threads_(threads) {}
  void share_out(std::size_t count, std::size_t grain,
                 const std::function<void(std::size_t, std::size_t)>& body) const override;

 private:
  int threads_;  // as --threads: 0 for every core
};

}  // namespace ncube

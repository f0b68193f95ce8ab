// The host's simplest help (radiosity/host_assist.h): the independent items of one compute
// step (a radiosity processor's receivers' form factors) shared out over host threads, and
// those form factors remembered across shots in the answer cache (a repeated shot asks
// about the same receivers with the same visibility).
//
// Contract (host side): it changes no answer and no count; each item is computed by the same
// function on the same inputs whichever thread takes it, and the results are used in item
// order (tests/host_threads_test.sh: result files equal for 1, 2 and 3 threads).
#pragma once

#include <cstdint>
#include <memory>

#include "host/host_side.h"
#include "host/scene_blockers.h"
#include "radiosity/host_assist.h"

namespace ncube {

class ThreadedAssist : public HostAssist {
 public:
  // `cache`: where the receivers' form factors are remembered across shots (answer_cache.h,
  // keyed by the shooter, the receivers' points and patches, and the visibility masks,
  // compared in full), or null.
  ThreadedAssist(int threads, std::shared_ptr<const SceneBlockers> cache);
  ~ThreadedAssist() override;
  void share_out(std::size_t count, std::size_t grain,
                 const std::function<void(std::size_t, std::size_t)>& body) const override;
  bool remembers_form_factors() const override { return blockers_ != nullptr; }
  bool remembered_form_factors(const Shooter& shooter, const PointBlock& receivers,
                               const PartMask* visible, double* out) override;
  void remember_form_factors(const Shooter& shooter, const PointBlock& receivers,
                             const PartMask* visible, const double* values) override;

 private:
  int threads_;  // as --threads: 0 for every core
  std::shared_ptr<const SceneBlockers> blockers_;  // holds the answer cache, or null
  std::uint64_t form_factor_set_;                  // the cache's id for these values
};

}  // namespace ncube

#include "host/threaded_assist.h"

#include "host/answer_cache.h"
#include "host/host_threads.h"

namespace ncube {

ThreadedAssist::ThreadedAssist(int threads, std::shared_ptr<const SceneBlockers> cache)
    : threads_(threads), blockers_(std::move(cache)), form_factor_set_(AnswerCache::new_set_id()) {}

ThreadedAssist::~ThreadedAssist() {
  if (blockers_) blockers_->answer_cache().forget_set(form_factor_set_);
}

void ThreadedAssist::share_out(std::size_t count, std::size_t grain,
                               const std::function<void(std::size_t, std::size_t)>& body) const {
  parallel_chunks(threads_, count, grain, body);
}

bool ThreadedAssist::remembered_form_factors(const Shooter& shooter, const PointBlock& receivers,
                                             const PartMask* visible, double* out) {
  return blockers_ && receivers.count > 0 &&
         blockers_->answer_cache().find_values(form_factor_set_, shooter, receivers, visible, out);
}

void ThreadedAssist::remember_form_factors(const Shooter& shooter, const PointBlock& receivers,
                                           const PartMask* visible, const double* values) {
  if (blockers_ && receivers.count > 0)
    blockers_->answer_cache().store_values(form_factor_set_, shooter, receivers, visible, values);
}

}  // namespace ncube

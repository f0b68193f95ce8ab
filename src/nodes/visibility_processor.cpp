#include "nodes/visibility_processor.h"

#include <xbt/log.h>

// --log=ncube_visibility.thresh:debug shows every block answered.
XBT_LOG_NEW_DEFAULT_CATEGORY(ncube_visibility, "the visibility processors (section 3)");

namespace ncube {

VisibilityProcessor::VisibilityProcessor(const ProgramSetup& setup, NodeRuntime& runtime,
                                         const OccluderSet& share)
    : setup_(setup), runtime_(runtime), share_(share) {}

void VisibilityProcessor::run() {
  runtime_.start();
  runtime_.charge(share_.build_work());  // section 6: the octree over the share, if any
  Shooter shooter;
  int iteration = 0;  // the trace's context: shooters received so far
  for (;;) {
    const std::unique_ptr<Message> message =
        runtime_.receive({MessageKind::kShooter, MessageKind::kPoints, MessageKind::kStop});
    if (message->kind == MessageKind::kStop) break;
    if (message->kind == MessageKind::kShooter) {
      runtime_.set_trace_context(++iteration, message->candidate.patch);
      shooter = make_shooter(setup_.scene, message->candidate.patch, message->candidate.unshot,
                             setup_.options.samples);
      continue;
    }
    // A block of points: one ray per point and shooter part, against this share's patches.
    auto answer = std::make_unique<Message>();
    answer->kind = MessageKind::kAnswers;
    answer->block = message->block;
    WorkCounts work;
    answer->masks.resize(message->points.size());
    share_.unblocked_parts(PointBlock(message->points, message->point_patches), shooter,
                           answer->masks.data(), work);
    count_blocked_rays(answer->masks.data(), answer->masks.size(), shooter, work);
    runtime_.charge(work);
    XBT_DEBUG("block %d from node %d: %zu points, %llu ray-patch tests", message->block,
              message->from, message->points.size(), (unsigned long long)work.ray_patch_tests);
    answer->mask_parts = setup_.options.samples;
    runtime_.send(message->from, std::move(answer));
  }
  runtime_.finish();
}

}  // namespace ncube

#include "simulation/host_machinery.h"

#include "host/fast_occluders.h"
#include "host/fast_octree.h"
#include "host/host_threads.h"
#include "host/lookahead.h"
#include "host/scene_blockers.h"
#include "host/threaded_assist.h"
#include "host/threaded_occluders.h"
#include "visibility/brute_force_occluders.h"
#include "visibility/octree.h"

namespace ncube {

void build_host_machinery(HostMachinery& machinery, const Scene& scene,
                          const std::vector<std::vector<int>>& patch_sets,
                          const ProgressiveOptions& options, int visibility_processors,
                          int radiosity_processors, int block_size, bool loads_change) {
  const bool reference = options.reference_visibility;
  const bool octree = options.visibility == VisibilityMethod::kOctree;
  std::vector<FastOccluders*> fast_sets;
  std::vector<FastOctree*> octree_sets;
  // With visibility processors and more than one host thread, the blocks' answers and form
  // factors are computed ahead on the other threads (lookahead.h).
  const int threads = resolve_host_threads(options.host_threads);
  const bool ahead = visibility_processors > 0 && threads > 1;
  for (const std::vector<int>& patches : patch_sets) {
    if (reference && octree) {
      machinery.occluders.push_back(std::make_unique<const Octree>(scene, patches));
    } else if (reference) {
      machinery.occluders.push_back(
          std::make_unique<const BruteForceOccluders>(scene, patches, options.ray_policy));
    } else if (octree && ahead) {
      auto set = std::make_unique<FastOctree>(std::make_unique<const Octree>(scene, patches));
      octree_sets.push_back(set.get());
      machinery.occluders.push_back(std::move(set));
    } else if (octree) {  // the block's points shared out over the host threads
      machinery.occluders.push_back(std::make_unique<const ThreadedOccluders>(
          std::make_unique<const FastOctree>(std::make_unique<const Octree>(scene, patches)),
          options.host_threads));
    } else {
      auto set = std::make_unique<FastOccluders>(scene, patches, options.ray_policy,
                                                 options.host_threads);
      fast_sets.push_back(set.get());
      machinery.occluders.push_back(std::move(set));
    }
  }
  if (reference) return;  // the program computes everything itself, on one thread
  if (ahead && octree) {
    auto lookahead = std::make_unique<Lookahead>(
        scene, std::vector<const FastOctree*>(octree_sets.begin(), octree_sets.end()), threads - 1);
    for (FastOctree* share : octree_sets) share->use_lookahead(lookahead.get());
    machinery.assist = std::move(lookahead);  // no guesses: the octree's answers are not kept
  } else if (ahead) {
    auto lookahead = std::make_unique<Lookahead>(
        scene, std::vector<const FastOccluders*>(fast_sets.begin(), fast_sets.end()), threads - 1);
    for (FastOccluders* share : fast_sets) share->use_lookahead(lookahead.get());
    // Guesses of the next shots need receivers that never change and do not depend on the
    // shooter.
    if (!loads_change && !options.skip_facing_away)
      lookahead->guess_shots(options.samples, block_size, radiosity_processors);
    machinery.assist = std::move(lookahead);
  } else {
    // Choice: the receivers' form factors remembered across shots without visibility
    // processors, where the brute-force set already holds the scene's answer cache (the
    // octree would build the scene's Embree scene for it). With V > 0 on one host thread they
    // are not: 150 iterations of scene3 R=8 V=7 gained nothing and held 130 MB more.
    const bool remember = visibility_processors == 0 && !fast_sets.empty();
    machinery.assist = std::make_unique<ThreadedAssist>(
        options.host_threads, remember ? SceneBlockers::for_scene(scene) : nullptr);
  }
}

}  // namespace ncube

// What a ray-patch test costs the host in each scene of scenes/ and in the probe's rooms, the
// probe's loop timed round by round in one process (src/tools/scene_test_cost.cpp;
// build/machine_probe --scenes, and --loop-only for a simulated-cache count of one run).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "counts/work_counts.h"

namespace ncube {

// One run of the visibility loop to time: `prepare` sets it up (and warms it) and returns one
// pass of its shots, which counts into the WorkCounts it is given.
struct LoopRun {
  std::string name;
  std::function<std::function<void(WorkCounts&)>()> prepare;
};

// The four scenes of scenes/, each with its patches tested in the scene's order and shuffled.
std::vector<LoopRun> scene_loop_runs();

// Prints one line per run (the probe's `rooms`, then the scenes in both orders); the platform
// file gives the rates taken off (ray_speed, blocked_ray_speed) and the test_speed compared
// with. Returns 0.
int print_scene_test_costs(int rounds, const std::string& platform_file,
                           const std::vector<LoopRun>& rooms);

// Sets up the one run named `name` (of `rooms` and the scenes) and runs its pass `passes`
// times, printing its counts of one pass: under a simulator of the caches (valgrind), two such
// processes' difference is what the passes cost (docs/machines/loop_profile.py). Exit 2 for an
// unknown name.
int run_loop_passes(const std::string& name, int passes, const std::vector<LoopRun>& rooms);

}  // namespace ncube

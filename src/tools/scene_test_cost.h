// What a ray-patch test costs the host in each scene of scenes/ and in the probe's rooms, the
// probe's loop timed round by round in one process (src/tools/scene_test_cost.cpp;
// build/machine_probe --scenes, and --loop-only for a simulated-cache count of one run).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "counts/work_counts.h"
#include "scene/scene.h"

namespace ncube {

// One run of the visibility loop to time: `prepare` sets it up (and warms it) and returns one
// pass of its shots, which counts into the WorkCounts it is given.
struct LoopRun {
  std::string name;
  std::function<std::function<void(WorkCounts&)>()> prepare;
};

// The four scenes of scenes/, each with its patches tested in the scene's order and shuffled.
std::vector<LoopRun> scene_loop_runs();

// The shooters a scene's runs take, as the probe's rooms: its brightest patch and three
// spread through its list.
std::vector<int> scene_shooter_patches(const Scene& scene);

// A run set up for timing: one pass, its counts, the passes a timed unit, the unit's times.
struct TimedPasses {
  std::string name;
  std::function<void(WorkCounts&)> pass;
  WorkCounts counts;  // of one pass
  int passes = 1;
  std::vector<double> seconds;
};

// Every run's timed unit (`passes` passes) once a round, one run after another, `rounds`
// rounds: the host's other work falls on all runs alike (thread CPU time).
void time_round_by_round(std::vector<TimedPasses>& runs, int rounds);

// The run of `runs` named `name` (exit 2 naming `option` and the runs for an unknown name).
const LoopRun& named_run(const std::string& option, const std::string& name,
                         const std::vector<LoopRun>& runs);

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

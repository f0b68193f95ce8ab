// What the hemicube costs the host in the scenes' runs and in the probe's rooms,
// render_hemicube timed round by round in one process (build/machine_probe --hemicube-scenes,
// and --hemicube-only for a simulated-cache count of one run; docs/machines/probe.md, "What a
// hemicube costs").
#pragma once

#include <string>
#include <vector>

#include "tools/scene_test_cost.h"

namespace ncube {

// The three hemicube rows of the prediction table (docs/machines/prediction_table.py): the
// Cornell box with a hemicube at each of the shooter's elements, scene0 at 400 x 400 cells,
// scene1 at the default 100 x 100; each from the scene's four shooters
// (scene_shooter_patches), every element of every other patch drawn, as a one-node run draws
// them.
std::vector<LoopRun> scene_hemicube_runs();

// Times every run of `rooms` (the probe's hemicube runs) and of scene_hemicube_runs() round by
// round, `rounds` rounds, and prints one line a run: its passes a timed unit, the median
// unit's seconds, the spread over rounds and every hemicube counter of one pass. Returns 0.
int print_hemicube_costs(int rounds, const std::vector<LoopRun>& rooms);

// Sets up the run named `name` and runs its pass `passes` times, printing its counters of one
// pass (for a simulator of the caches: two such processes' difference is one pass). Exit 2
// for an unknown name.
int run_hemicube_passes(const std::string& name, int passes, const std::vector<LoopRun>& rooms);

}  // namespace ncube

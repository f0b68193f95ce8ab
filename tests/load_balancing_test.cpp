// Dynamic load balancing (paper section 4.2; nodes/load_balancing.h): the master's rule on
// loads worked out by hand, the sender's choice, the bytes of a patch, and in a simulated
// run the memory each node holds after cuts and transfers.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "machine/cost_model.h"
#include "machine/platform_config.h"
#include "nodes/memory_plan.h"
#include "scene/scene_loader.h"
#include "simulation/simulation.h"

namespace ncube {
namespace {

std::string repo(const std::string& path) { return std::string(NCUBE_SOURCE_DIR) + "/" + path; }

TEST(BalancingRule, PairsTheMostLoadedWithTheLeastLoaded) {
  // Elements 100, 400, 250, 50 (mean 200): only rank 1 is above 1.2 x 200 = 240 ... and
  // rank 2 (250) too. Rank 1 pairs with rank 3 (least loaded): min(400 - 200, 200 - 50) =
  // 150 elements; rank 2 with rank 0: min(50, 100) = 50.
  std::vector<ProcessorLoad> loads{{0, 100, 1e6, 0, 1e3, 10}, {1, 400, 2e6, 0, 1e3, 10},
                                   {2, 250, 1e6, 0, 1e3, 10}, {3, 50, 3e6, 0, 1e3, 10}};
  BalancingOptions o;
  o.enabled = true;
  const BalanceDecision d = plan_transfers(loads, 4e6, o);
  ASSERT_EQ(d.transfers.size(), 2u);
  EXPECT_EQ(d.transfers[0].from, 1);
  EXPECT_EQ(d.transfers[0].to, 3);
  EXPECT_EQ(d.transfers[0].elements, 150);
  EXPECT_DOUBLE_EQ(d.transfers[0].bytes, 0.5 * (4e6 - 3e6));  // half the receiver's room
  EXPECT_EQ(d.transfers[1].from, 2);
  EXPECT_EQ(d.transfers[1].to, 0);
  EXPECT_EQ(d.transfers[1].elements, 50);
  // A sender whose smallest movable patch is larger than its order gets no order (it could
  // move nothing); the next most loaded still pairs with the least loaded.
  loads[1].smallest_patch_elements = 151;
  const BalanceDecision d2 = plan_transfers(loads, 4e6, o);
  ASSERT_EQ(d2.transfers.size(), 1u);
  EXPECT_EQ(d2.transfers[0].from, 2);
  EXPECT_EQ(d2.transfers[0].to, 3);
  EXPECT_EQ(d2.transfers[0].elements, 50);  // min(250 - 200, 200 - 50)
  loads[1].smallest_patch_elements = 150;  // fits exactly
  EXPECT_EQ(plan_transfers(loads, 4e6, o).transfers.size(), 2u);
  loads[1].smallest_patch_elements = 0;  // nothing movable
  EXPECT_EQ(plan_transfers(loads, 4e6, o).transfers.size(), 1u);
  loads[1].smallest_patch_elements = 10;
  // Below the threshold nothing moves; switched off nothing moves.
  o.threshold = 1.5;  // 2.5 x 200 = 500 > 400
  EXPECT_TRUE(plan_transfers(loads, 4e6, o).transfers.empty());
  o.enabled = false;
  o.threshold = 0.2;
  EXPECT_TRUE(plan_transfers(loads, 4e6, o).transfers.empty());
}

TEST(BalancingRule, ShortOfMemoryGivesToTheEmptiestOrFails) {
  std::vector<ProcessorLoad> loads{{0, 100, 3.9e6, 5000, 2e5, 10}, {1, 100, 1e6, 0, 1e3, 10},
                                   {2, 100, 2e6, 0, 1e3, 10}};
  BalancingOptions o;
  o.enabled = true;
  BalanceDecision d = plan_transfers(loads, 4e6, o);
  ASSERT_EQ(d.transfers.size(), 1u);
  EXPECT_EQ(d.transfers[0].from, 0);
  EXPECT_EQ(d.transfers[0].to, 1);  // the most free memory
  EXPECT_DOUBLE_EQ(d.transfers[0].bytes, 1.5e6);
  EXPECT_EQ(d.out_of_memory_rank, -1);
  // Its smallest patch does not fit in half the room anywhere: out of memory.
  loads[0].smallest_patch_bytes = 1.6e6;
  d = plan_transfers(loads, 4e6, o);
  EXPECT_EQ(d.out_of_memory_rank, 0);
  EXPECT_DOUBLE_EQ(d.out_of_memory_needed, 3.9e6 + 5000);
  // Without balancing, running short is the end.
  loads[0].smallest_patch_bytes = 2e5;
  o.enabled = false;
  EXPECT_EQ(plan_transfers(loads, 4e6, o).out_of_memory_rank, 0);
}

TEST(BalancingTransfer, LargestPatchesFirstWithinTheOrderNeverTheShooter) {
  const Scene scene = load_scene(repo("scenes/cornell-box.json"));
  std::vector<int> all(scene.patches.size());
  std::iota(all.begin(), all.end(), 0);
  const ElementStore store(scene, all);
  const CostModel costs = load_cost_model(repo("platforms/cost_model.json"));
  // A patch's bytes: its radiosity data, its geometry when asked, its element records.
  const StoredPatch& first = store.patches()[0];
  EXPECT_DOUBLE_EQ(patch_bytes(scene, first, costs, true),
                   costs.patch_radiosity_bytes + costs.patch_geometry_bytes +
                       double(first.elements.size()) * costs.element_bytes);
  // The largest patch (most elements, lowest index on ties) goes first unless it is the shooter.
  int largest = 0;
  for (int p = 0; p < int(scene.patches.size()); ++p)
    if (scene.patches[p].element_count() > scene.patches[largest].element_count()) largest = p;
  const long n = scene.patches[largest].element_count();
  Transfer t{0, 1, n, 1e9};
  EXPECT_EQ(patches_to_move(store, t, -1, costs, true), std::vector<int>{largest});
  const std::vector<int> without = patches_to_move(store, t, largest, costs, true);
  EXPECT_TRUE(std::find(without.begin(), without.end(), largest) == without.end());
  long moved = 0;
  for (int p : without) moved += scene.patches[p].element_count();
  EXPECT_LE(moved, n);
  EXPECT_GT(moved, 0);
  t.bytes = 1.0;  // nothing fits
  EXPECT_TRUE(patches_to_move(store, t, -1, costs, true).empty());
}

// Every radiosity processor's bytes at the end are its start (memory plan) plus, for every
// patch it holds at the end, what that patch weighs, minus what its starting patches
// weighed: cuts add 4 element records, a transfer moves a patch's bytes.
void expect_memory_follows_the_elements(int R, int V, bool balance, int iterations) {
  const Scene scene = load_scene(repo("scenes/scene1.json"));
  const CostModel costs = load_cost_model(repo("platforms/cost_model.json"));
  SimulationConfig config;
  config.radiosity_processors = R;
  config.visibility_processors = V;
  config.options.max_iterations = iterations;
  config.options.samples = 16;  // M = 16, as when it was the default
  config.options.subdivision.enabled = true;
  config.balancing.enabled = balance;
  const SimulationResult r =
      run_simulation(scene, config, load_platform_config(repo("platforms/ncube2.json")), costs);
  ASSERT_EQ(r.status, RunStatus::kOk);
  const std::vector<std::vector<int>> start = partition_patches_by_elements(scene, R);
  const bool with_geometry = V > 0;
  long cut_total = 0, records_total = 0;
  for (int rank = 0; rank < R; ++rank) {
    const NodeStats& node = r.nodes[std::size_t(rank * (V + 1))];
    ASSERT_EQ(node.role, NodeRole::kRadiosity);
    double expected = 0.0;
    // Starting bytes from the plan: the node's first bytes are its peak when nothing grew.
    const ProgramSetup setup{scene, Placement{R, V}, config, 0.0};
    expected = plan_memory(setup, start, costs)[std::size_t(rank * (V + 1))].bytes;
    for (int p : start[std::size_t(rank)])
      expected -= costs.patch_radiosity_bytes + (with_geometry ? costs.patch_geometry_bytes : 0.0) +
                  scene.patches[std::size_t(p)].element_count() * costs.element_bytes;
    for (int p : r.held_patches[std::size_t(rank)]) {
      const PatchSolution& s = r.solution[std::size_t(p)];
      const long cuts = (long(s.cells.size()) - scene.patches[std::size_t(p)].element_count()) / 3;
      cut_total += cuts;
      records_total += scene.patches[std::size_t(p)].element_count() + 4 * cuts;
      expected += costs.patch_radiosity_bytes + (with_geometry ? costs.patch_geometry_bytes : 0.0) +
                  double(scene.patches[std::size_t(p)].element_count() + 4 * cuts) * costs.element_bytes;
    }
    EXPECT_NEAR(node.memory_bytes_at_end, expected, 1e-6) << "rank " << rank;
    EXPECT_GE(node.peak_memory_bytes, node.memory_bytes_at_end);
  }
  EXPECT_EQ(std::uint64_t(4 * cut_total), r.counts.elements_created);
  EXPECT_GT(cut_total, 0);
  if (balance) {
    EXPECT_GT(r.patches_moved, 0);
  }
}

TEST(BalancingMemory, AfterCutsWithoutBalancing) { expect_memory_follows_the_elements(4, 0, false, 8); }
TEST(BalancingMemory, AfterCutsAndTransfersWithVisibilityProcessors) {
  expect_memory_follows_the_elements(4, 1, true, 5);
}
TEST(BalancingMemory, AfterCutsAndTransfersWithoutVisibilityProcessors) {
  expect_memory_follows_the_elements(8, 0, true, 8);
}

}  // namespace
}  // namespace ncube

// One simulated run, end to end, on a scene small enough to count by hand: every counted
// operation, every message and byte, and each node's message overhead are pinned against
// values worked out below (not computed by the simulator's own formulas), so that a wrong
// cost, block rule or count fails here. Plus the run's failure modes. Each TEST runs its
// own SimGrid Engine, hence its own process under ctest.
#include <gtest/gtest.h>

#include <climits>

#include "hand_counted_scene.h"
#include "machine/cost_model.h"
#include "machine/platform_config.h"
#include "simulation/simulation.h"
#include "util/input_error.h"

namespace ncube {
namespace {

std::string repo(const std::string& path) { return std::string(NCUBE_SOURCE_DIR) + "/" + path; }

// The nCube2's per-message software overhead on each side, from its source (LogP, Culler
// et al. 1993: about 160 us per send and receive pair on Vertex), not from ncube2.json.
constexpr double kOverheadPerMessage = 80e-6;

SimulationResult run(int R, int V, int block_size = 2, bool pipelined = false) {
  SimulationConfig config;
  config.radiosity_processors = R;
  config.visibility_processors = V;
  config.options.samples = 4;
  config.options.max_iterations = 1;
  config.block_size = block_size;
  config.pipelined = pipelined;
  return run_simulation(hand_counted_scene(), config,
                        load_platform_config(repo("platforms/ncube2.json")),
                        load_cost_model(repo("platforms/cost_model.json")));
}

WorkCounts counts(std::uint64_t candidates, std::uint64_t receivers, std::uint64_t rays,
                  std::uint64_t tests, std::uint64_t crossings, std::uint64_t form_factors,
                  std::uint64_t updates) {
  WorkCounts c;
  c.shooter_candidates = candidates;
  c.receivers = receivers;
  c.rays = rays;
  c.ray_patch_tests = tests;
  c.plane_crossings = crossings;
  c.form_factors = form_factors;
  c.element_updates = updates;
  return c;
}

void expect_counts(const WorkCounts& got, const WorkCounts& want, const std::string& who) {
  EXPECT_EQ(got.shooter_candidates, want.shooter_candidates) << who;
  EXPECT_EQ(got.receivers, want.receivers) << who;
  EXPECT_EQ(got.rays, want.rays) << who;
  EXPECT_EQ(got.ray_patch_tests, want.ray_patch_tests) << who;
  EXPECT_EQ(got.plane_crossings, want.plane_crossings) << who;
  EXPECT_EQ(got.form_factors, want.form_factors) << who;
  EXPECT_EQ(got.element_updates, want.element_updates) << who;
}

// The partition (section 4, largest first to the least loaded, ties to the lower rank):
// floor (5) -> rank 0, table (3) -> rank 1, wall (2) -> rank 1, light (1) -> rank 0 (5 = 5).
// Rank 0 owns patches {0, 1}: 6 elements, 5 receivers (the floor); rank 1 owns {2, 3}: 5
// elements, all receivers.
//
// Rays and tests (brute force, section 2.2): each ray is tested against every patch but the
// shooter and the receiver's own. Plane crossings: the floor's rays rise from y = 0 to
// y = 2 through the table's plane y = 1 (20 rays); the wall's lower element (y = 0.4) too
// (4 rays); no ray crosses the floor's plane (all above it) or the wall's (all at x < 5).
// Every ray is unblocked (the table lies beside the floor, below the wall's rays), and
// every receiver is in front of the light: 4 form factors per receiver.
// Shooter candidates: two selection rounds (shoot, then stop), each comparing the owned
// patches, plus the master's comparison of rank 1's candidate in each round.
TEST(SimulationCounts, EveryOperationWithoutVisibilityProcessors) {
  const SimulationResult r = run(2, 0);
  ASSERT_EQ(r.status, RunStatus::kOk);
  ASSERT_EQ(r.shooters, std::vector<int>({0}));
  ASSERT_EQ(r.nodes.size(), 2u);
  // rank 0: floor rays test table and wall: 20 rays x 2 = 40 tests, 20 crossings.
  expect_counts(r.nodes[0].counts, counts(2 * 2 + 2, 6, 20, 40, 20, 20, 5), "rank 0");
  // rank 1: table rays test floor and wall (12 x 2), wall rays floor and table (8 x 2).
  expect_counts(r.nodes[1].counts, counts(2 * 2, 5, 20, 40, 4, 20, 5), "rank 1");
  expect_counts(r.counts, counts(10, 11, 40, 80, 24, 40, 10), "all");
}

// V = 2: visibility processor j of each group holds share j of the patches, {0, 1} (light,
// floor) or {2, 3} (table, wall), and traces every point of its group against it.
TEST(SimulationCounts, EveryOperationWithVisibilityProcessors) {
  const SimulationResult r = run(2, 2);
  ASSERT_EQ(r.status, RunStatus::kOk);
  ASSERT_EQ(r.nodes.size(), 6u);  // nodes 0 (rank 0), 1, 2, 3 (rank 1), 4, 5
  expect_counts(r.nodes[0].counts, counts(2 * 2 + 2, 6, 0, 0, 0, 20, 5), "rank 0");
  // Floor points against {light, floor}: both skipped (shooter, own patch).
  expect_counts(r.nodes[1].counts, counts(0, 0, 20, 0, 0, 0, 0), "visibility 0.0");
  // Floor points against {table, wall}: 40 tests, the table's plane crossed by all 20.
  expect_counts(r.nodes[2].counts, counts(0, 0, 20, 40, 20, 0, 0), "visibility 0.1");
  expect_counts(r.nodes[3].counts, counts(2 * 2, 5, 0, 0, 0, 20, 5), "rank 1");
  // Table and wall points against the floor only (the light is the shooter): 20 tests.
  expect_counts(r.nodes[4].counts, counts(0, 0, 20, 20, 0, 0, 0), "visibility 1.0");
  // Table points against the wall (12), wall points against the table (8, 4 crossing).
  expect_counts(r.nodes[5].counts, counts(0, 0, 20, 20, 4, 0, 0), "visibility 1.1");
}

// Messages of one iteration and the stop, with B = 2 points per block and V = 2.
// Each radiosity processor has 5 receivers: ceil(5 / 2) = 3 blocks of 2, 2 and 1 points,
// each sent to both visibility processors (6 messages of 16-byte points: 2 x (40 + 40 + 24)
// = 208 bytes with the 8-byte headers), answered by one 1-byte mask per point (4 samples):
// 3 answers per visibility processor of 10, 10 and 9 bytes.
// Shooter selection (binomial tree over R = 2): rank 1 sends its candidate to rank 0, rank 0
// sends the decision back, in both rounds (shooter, then stop); every radiosity processor
// tells its 2 visibility processors the shooter and then the stop. Those records are 88
// bytes + 8 header.
TEST(SimulationMessages, PointBlocksAnswersAndTreeMessages) {
  const SimulationResult r = run(2, 2);
  ASSERT_EQ(r.status, RunStatus::kOk);
  ASSERT_EQ(r.nodes.size(), 6u);
  const double record = 88 + 8;
  for (int rank : {0, 1}) {
    const NodeStats& rp = r.nodes[std::size_t(3 * rank)];
    EXPECT_EQ(rp.messages_sent, 2 + 4 + 6) << "rank " << rank;
    EXPECT_DOUBLE_EQ(rp.bytes_sent, 2 * record + 4 * record + 208) << "rank " << rank;
    EXPECT_EQ(rp.messages_received, 2 + 6) << "rank " << rank;
    EXPECT_NEAR(rp.overhead_seconds, (12 + 8) * kOverheadPerMessage, 1e-12) << "rank " << rank;
    for (int j : {1, 2}) {
      const NodeStats& vp = r.nodes[std::size_t(3 * rank + j)];
      EXPECT_EQ(vp.messages_sent, 3) << "visibility " << rank << "." << j - 1;
      EXPECT_DOUBLE_EQ(vp.bytes_sent, 10 + 10 + 9) << "visibility " << rank << "." << j - 1;
      EXPECT_EQ(vp.messages_received, 1 + 3 + 1) << "visibility " << rank << "." << j - 1;
      EXPECT_NEAR(vp.overhead_seconds, (3 + 5) * kOverheadPerMessage, 1e-12);
    }
  }
}

// The same blocks whether or not the next block is sent ahead (pipelined).
TEST(SimulationMessages, PipelinedSendsTheSameBlocks) {
  const SimulationResult pipelined = run(2, 2, 2, true);
  ASSERT_EQ(pipelined.status, RunStatus::kOk);
  EXPECT_EQ(pipelined.nodes[0].messages_sent, 2 + 4 + 6);
  EXPECT_DOUBLE_EQ(pipelined.nodes[0].bytes_sent, 6 * (88 + 8) + 208);
}

// A block size that divides the receivers evenly: B = 5 gives one block of 5 points (88
// bytes) per visibility processor.
TEST(SimulationMessages, BlockCountFollowsTheBlockSize) {
  const SimulationResult whole = run(2, 2, 5);
  ASSERT_EQ(whole.status, RunStatus::kOk);
  EXPECT_EQ(whole.nodes[0].messages_sent, 2 + 4 + 2);
  EXPECT_DOUBLE_EQ(whole.nodes[0].bytes_sent, 6 * (88 + 8) + 2 * (5 * 16 + 8));
  EXPECT_EQ(whole.nodes[1].messages_sent, 1);
  EXPECT_DOUBLE_EQ(whole.nodes[1].bytes_sent, 5 + 8);
}

// Without visibility processors only the tree messages remain: rank 1 sends 2 candidates
// and receives 2 decisions; rank 0 the reverse.
TEST(SimulationMessages, TreeMessagesOnlyWithoutVisibilityProcessors) {
  const SimulationResult r = run(2, 0);
  ASSERT_EQ(r.status, RunStatus::kOk);
  for (const NodeStats& n : r.nodes) {
    EXPECT_EQ(n.messages_sent, 2) << n.node;
    EXPECT_EQ(n.messages_received, 2) << n.node;
    EXPECT_DOUBLE_EQ(n.bytes_sent, 2 * (88 + 8)) << n.node;
    EXPECT_NEAR(n.overhead_seconds, 4 * kOverheadPerMessage, 1e-12) << n.node;
  }
}

// ------------------------------------------------------------------ failure modes

TEST(SimulationFailure, NodeCountIsComputedWithoutOverflow) {
  // R x (V + 1) with V = 2^31 - 1 overflows an int; the check must still refuse it.
  const Scene scene = hand_counted_scene();
  SimulationConfig config;
  config.options.samples = 16;  // M = 16, as when it was the default
  config.radiosity_processors = 2;
  config.visibility_processors = INT_MAX;
  EXPECT_THROW(check_configuration(scene, config, load_platform_config(repo("platforms/ncube2.json"))),
               InputError);
}

TEST(SimulationFailure, NodeThatDoesNotFinishGivesFailedStatus) {
  // A node so slow (bypassing the platform file's bounds) that its first batch of work
  // would end beyond the largest double: SimGrid reports a deadlock and stops with the node
  // blocked. The run must say so instead of reporting status ok.
  PlatformConfig platform = load_platform_config(repo("platforms/ncube2.json"));
  platform.node_speed = 1e-305;
  SimulationConfig config;
  config.options.samples = 4;
  const SimulationResult r = run_simulation(hand_counted_scene(), config, platform,
                                            load_cost_model(repo("platforms/cost_model.json")));
  EXPECT_EQ(r.status, RunStatus::kFailed);
  EXPECT_NE(r.failure.find("did not finish"), std::string::npos) << r.failure;
}

TEST(SimulationFailure, OutOfMemoryNeedsNoElements) {
  // The memory check uses the patches' element counts: a scene too large for the modeled
  // machine is refused before the host builds its elements.
  Scene scene = hand_counted_scene();
  scene.patches[1].nu = 1024;
  scene.patches[1].nv = 1024;
  scene.elements.clear();
  scene.derive_patch_fields();
  SimulationConfig config;
  config.options.samples = 16;  // M = 16, as when it was the default
  const PlatformConfig platform = load_platform_config(repo("platforms/ncube2.json"));
  const CostModel costs = load_cost_model(repo("platforms/cost_model.json"));
  const OutOfMemory first = first_node_out_of_memory(scene, config, platform, costs);
  EXPECT_EQ(first.node, 0);
  const SimulationResult r = run_simulation(scene, config, platform, costs);
  EXPECT_EQ(r.status, RunStatus::kOutOfMemory);
  EXPECT_EQ(r.out_of_memory.node, 0);
  EXPECT_DOUBLE_EQ(r.out_of_memory.needed_bytes, first.needed_bytes);
}

}  // namespace
}  // namespace ncube

namespace ncube {
namespace {

// The result file's strings for the statuses and roles (docs/result-format.md).
TEST(SimulationNames, StatusesAndRolesKeepTheirResultFileNames) {
  EXPECT_STREQ(status_name(RunStatus::kOk), "ok");
  EXPECT_STREQ(status_name(RunStatus::kOutOfMemory), "out_of_memory");
  EXPECT_STREQ(status_name(RunStatus::kFailed), "failed");
  EXPECT_STREQ(role_name(NodeRole::kRadiosity), "radiosity");
  EXPECT_STREQ(role_name(NodeRole::kVisibility), "visibility");
  EXPECT_STREQ(role_name(NodeRole::kRendering), "rendering");
}

}  // namespace
}  // namespace ncube

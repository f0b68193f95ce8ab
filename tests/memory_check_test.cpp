// The memory check before a run (src/simulation/memory_check.h) at the edge: a node whose
// modeled bytes are exactly the node's memory fits, one byte more does not. The bytes are
// worked out by hand from the record sizes of platforms/cost_model.json on the hand-counted
// scene (as in tests/memory_plan_test.cpp).
#include "simulation/memory_check.h"

#include <gtest/gtest.h>

#include "hand_counted_scene.h"
#include "machine/cost_model.h"
#include "machine/platform_config.h"
#include "simulation/simulation.h"

namespace ncube {
namespace {

std::string repo(const std::string& path) { return std::string(NCUBE_SOURCE_DIR) + "/" + path; }

// R = 2, V = 0: rank 0 (node 0) holds the reserve, two shooter records, the geometry of all 4
// patches, its own 2 patches' radiosities and their 6 elements; rank 1 one element fewer.
// With the committed record sizes: 786432 + 2 x 88 + 4 x 68 + 2 x 48 + 6 x 184 = 788080 bytes.
double busiest_node_bytes(const CostModel& c) {
  return c.node_reserve_bytes + 2 * c.shooter_record_bytes + 4 * c.patch_geometry_bytes +
         2 * c.patch_radiosity_bytes + 6 * c.element_bytes;
}

SimulationConfig two_radiosity_processors() {
  SimulationConfig config;
  config.radiosity_processors = 2;
  config.options.max_iterations = 1;
  return config;
}

TEST(MemoryCheck, ANodeThatFillsItsMemoryExactlyFits) {
  const Scene scene = hand_counted_scene();
  const CostModel costs = load_cost_model(repo("platforms/cost_model.json"));
  PlatformConfig platform = load_platform_config(repo("platforms/ncube2.json"));
  const double full = busiest_node_bytes(costs);
  ASSERT_GT(platform.node_memory, full);  // the edge is set below, by hand
  platform.node_memory = full;
  EXPECT_EQ(first_node_out_of_memory(scene, two_radiosity_processors(), platform, costs).node, -1);
  // One byte less: node 0 is over (node 1, 184 bytes lighter, still fits).
  platform.node_memory = full - 1;
  const OutOfMemory over = first_node_out_of_memory(scene, two_radiosity_processors(), platform, costs);
  EXPECT_EQ(over.node, 0);
  EXPECT_EQ(over.role, NodeRole::kRadiosity);
  EXPECT_DOUBLE_EQ(over.needed_bytes, full);
  EXPECT_DOUBLE_EQ(over.available_bytes, full - 1);
  platform.node_memory = full - costs.element_bytes;  // exactly node 1's bytes
  EXPECT_EQ(first_node_out_of_memory(scene, two_radiosity_processors(), platform, costs).node, 0);
}

// The same edge in a whole run: at exactly full memory it runs, one byte less it stops
// before it starts, out of memory at node 0.
TEST(MemoryCheck, ARunAtExactlyFullMemoryRuns) {
  const Scene scene = hand_counted_scene();
  const CostModel costs = load_cost_model(repo("platforms/cost_model.json"));
  PlatformConfig platform = load_platform_config(repo("platforms/ncube2.json"));
  platform.node_memory = busiest_node_bytes(costs);
  const SimulationResult fits = run_simulation(scene, two_radiosity_processors(), platform, costs);
  EXPECT_EQ(fits.status, RunStatus::kOk);
  EXPECT_EQ(fits.iterations, 1);
  platform.node_memory -= 1;
  const SimulationResult over = run_simulation(scene, two_radiosity_processors(), platform, costs);
  EXPECT_EQ(over.status, RunStatus::kOutOfMemory);
  EXPECT_EQ(over.out_of_memory.node, 0);
}

}  // namespace
}  // namespace ncube

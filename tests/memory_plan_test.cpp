// The memory plan per role (sections 2.2 and 3) on the hand-counted scene, against byte
// counts worked out by hand from the record sizes of platforms/cost_model.json.
#include "nodes/memory_plan.h"

#include <gtest/gtest.h>

#include "hand_counted_scene.h"
#include "machine/cost_model.h"

namespace ncube {
namespace {

std::string repo(const std::string& path) { return std::string(NCUBE_SOURCE_DIR) + "/" + path; }

std::vector<NodeMemory> plan(const Scene& scene, int R, int V, int block_size, bool pipelined) {
  const ProgramSetup setup{scene, Placement{R, V}, ProgressiveOptions{}, 1.0, block_size, pipelined};
  return plan_memory(setup, partition_patches_by_elements(scene, R),
                     load_cost_model(repo("platforms/cost_model.json")));
}

// R = 2: rank 0 owns the light and the floor (2 patches, 6 elements), rank 1 the table and
// the wall (2 patches, 5 elements). Every node holds the reserve and two shooter records.
TEST(MemoryPlan, WithoutVisibilityProcessorsEveryRadiosityProcessorHoldsAllGeometry) {
  const CostModel c = load_cost_model(repo("platforms/cost_model.json"));
  const auto nodes = plan(hand_counted_scene(), 2, 0, 100, false);
  ASSERT_EQ(nodes.size(), 2u);
  const double base = c.node_reserve_bytes + 2 * c.shooter_record_bytes;
  // Section 2.2: the geometry of all 4 patches, to trace rays through the whole scene.
  EXPECT_DOUBLE_EQ(nodes[0].bytes, base + 4 * c.patch_geometry_bytes + 2 * c.patch_radiosity_bytes +
                                       6 * c.element_bytes);
  EXPECT_DOUBLE_EQ(nodes[1].bytes, base + 4 * c.patch_geometry_bytes + 2 * c.patch_radiosity_bytes +
                                       5 * c.element_bytes);
  EXPECT_EQ(nodes[0].role, "radiosity");
  EXPECT_EQ(nodes[1].node, 1);
}

// R = 2, V = 2, B = 3: a radiosity processor holds only its own patches' geometry plus one
// block of points out and V blocks of answers in (4 samples: 1-byte masks); a visibility
// processor holds its share (2 patches) and one block of points and of answers. Pipelined,
// two blocks are in flight.
TEST(MemoryPlan, WithVisibilityProcessorsEachRoleHoldsItsShare) {
  const CostModel c = load_cost_model(repo("platforms/cost_model.json"));
  const Scene scene = hand_counted_scene();
  const double base = c.node_reserve_bytes + 2 * c.shooter_record_bytes;
  for (const bool pipelined : {false, true}) {
    const double in_flight = pipelined ? 2 : 1;
    const auto nodes = plan(scene, 2, 2, 3, pipelined);
    ASSERT_EQ(nodes.size(), 6u);
    // Default samples: 16, so each answer is a 2-byte mask.
    const double rp_blocks = in_flight * 3 * (c.point_bytes + 2 * 2);
    const double vp_blocks = in_flight * 3 * (c.point_bytes + 2);
    EXPECT_DOUBLE_EQ(nodes[0].bytes, base + 2 * c.patch_geometry_bytes + 2 * c.patch_radiosity_bytes +
                                         6 * c.element_bytes + rp_blocks);
    EXPECT_DOUBLE_EQ(nodes[3].bytes, base + 2 * c.patch_geometry_bytes + 2 * c.patch_radiosity_bytes +
                                         5 * c.element_bytes + rp_blocks);
    for (int node : {1, 2, 4, 5}) {
      EXPECT_EQ(nodes[std::size_t(node)].role, "visibility");
      EXPECT_DOUBLE_EQ(nodes[std::size_t(node)].bytes, base + 2 * c.patch_geometry_bytes + vp_blocks)
          << "node " << node;
    }
  }
}

}  // namespace
}  // namespace ncube

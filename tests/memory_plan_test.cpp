// The memory plan per role (sections 2.2 and 3) on the hand-counted scene, against byte
// counts worked out by hand from the record sizes of platforms/cost_model.json.
#include "nodes/memory_plan.h"

#include <gtest/gtest.h>

#include "hand_counted_scene.h"
#include "machine/cost_model.h"
#include "visibility/octree.h"

namespace ncube {
namespace {

std::string repo(const std::string& path) { return std::string(NCUBE_SOURCE_DIR) + "/" + path; }

// M = 16 (the paper's smaller M): the bytes below were counted with it, when it was the
// default of ProgressiveOptions.
ProgressiveOptions sixteen_samples() {
  ProgressiveOptions options;
  options.samples = 16;
  return options;
}

ProgramOptions program_options(const ProgressiveOptions& algorithm, int block_size, bool pipelined) {
  ProgramOptions options;
  options.options = algorithm;
  options.block_size = block_size;
  options.pipelined = pipelined;
  return options;
}

std::vector<NodeMemory> plan(const Scene& scene, int R, int V, int block_size, bool pipelined) {
  const ProgramSetup setup{scene, Placement{R, V}, program_options(sixteen_samples(), block_size, pipelined), 1.0};
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
  EXPECT_EQ(nodes[0].role, NodeRole::kRadiosity);
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
    // 16 samples (sixteen_samples()), so each answer is a 2-byte mask.
    const double rp_blocks = in_flight * 3 * (c.point_bytes + 2 * 2);
    const double vp_blocks = in_flight * 3 * (c.point_bytes + 2);
    EXPECT_DOUBLE_EQ(nodes[0].bytes, base + 2 * c.patch_geometry_bytes + 2 * c.patch_radiosity_bytes +
                                         6 * c.element_bytes + rp_blocks);
    EXPECT_DOUBLE_EQ(nodes[3].bytes, base + 2 * c.patch_geometry_bytes + 2 * c.patch_radiosity_bytes +
                                         5 * c.element_bytes + rp_blocks);
    for (int node : {1, 2, 4, 5}) {
      EXPECT_EQ(nodes[std::size_t(node)].role, NodeRole::kVisibility);
      EXPECT_DOUBLE_EQ(nodes[std::size_t(node)].bytes, base + 2 * c.patch_geometry_bytes + vp_blocks)
          << "node " << node;
    }
  }
}

// Section 6, --visibility octree: a node that tests rays also holds an octree over its set.
// The hand-counted scene's 4 patches fit in one leaf (at most 8 per leaf): the whole-scene
// octree is the root cell and 4 patch references; a share of 2 patches (V = 2) the root and
// 2 references. Radiosity processors with V > 0 hold none.
TEST(MemoryPlan, OctreeVisibilityAddsTheOctreeOfEachNodeThatTestsRays) {
  const CostModel c = load_cost_model(repo("platforms/cost_model.json"));
  EXPECT_DOUBLE_EQ(c.octree_cell_bytes, 64);  // 6 floats, 8 pointers, list pointer and count
  EXPECT_DOUBLE_EQ(c.octree_reference_bytes, 4);
  const Scene scene = hand_counted_scene();
  ProgressiveOptions octree = sixteen_samples();
  octree.visibility = "octree";
  for (const int V : {0, 2}) {
    const auto partition = partition_patches_by_elements(scene, 2);
    const auto brute = plan_memory(ProgramSetup{scene, Placement{2, V}, program_options(sixteen_samples(), 3, false), 1.0},
                                   partition, c);
    const auto with = plan_memory(ProgramSetup{scene, Placement{2, V}, program_options(octree, 3, false), 1.0}, partition, c);
    ASSERT_EQ(brute.size(), with.size());
    for (std::size_t n = 0; n < with.size(); ++n) {
      const double expected = V == 0 ? 64 + 4 * 4 : (with[n].role == NodeRole::kVisibility ? 64 + 2 * 4 : 0);
      EXPECT_DOUBLE_EQ(with[n].bytes - brute[n].bytes, expected) << "V = " << V << ", node " << n;
    }
  }
  // Any 2 patches share the root with the default parameters: 1 cell, 2 references.
  EXPECT_DOUBLE_EQ(c.bytes(Octree(scene, {1, 3}).structure_items()), 64 + 2 * 4);
}

}  // namespace
}  // namespace ncube

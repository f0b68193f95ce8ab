#include "nodes/placement.h"

#include <algorithm>
#include <gtest/gtest.h>

#include "machine/cost_model.h"
#include "machine/platform_config.h"
#include "nodes/memory_plan.h"
#include "scene/scene_loader.h"

namespace ncube {
namespace {

std::string repo(const std::string& path) { return std::string(NCUBE_SOURCE_DIR) + "/" + path; }

TEST(Placement, GroupsArePowerOfTwoSubcubesWithNeighbouringRadiosityProcessors) {
  const Placement p{8, 7};
  for (int r = 0; r < 8; ++r) {
    EXPECT_EQ(p.radiosity_node(r), 8 * r);
    for (int j = 0; j < 7; ++j)  // same high bits: inside the 3-subcube of the group
      EXPECT_EQ(p.visibility_node(r, j) >> 3, r);
  }
  for (int r = 0; r < 8; ++r)
    for (int d = 0; d < 3; ++d)
      EXPECT_EQ(__builtin_popcount(unsigned(p.radiosity_node(r) ^ p.radiosity_node(r ^ (1 << d)))), 1);
}

TEST(Placement, OtherGroupSizesUseConsecutiveNodes) {
  const Placement p{5, 11};  // the paper's 60-node substitute for R=4, V=15
  EXPECT_EQ(p.node_count(), 60);
  EXPECT_EQ(p.radiosity_node(4), 48);
  EXPECT_EQ(p.visibility_node(4, 10), 59);
}

TEST(Partition, BalancesElementsAndAssignsEveryPatchOnce) {
  const Scene scene = load_scene(repo("scenes/scene2.json"));
  for (int R : {3, 8, 64}) {
    const auto owned = partition_patches_by_elements(scene, R);
    std::vector<int> seen(scene.patches.size(), 0);
    long lo = 1L << 40, hi = 0;
    int biggest = 0;
    for (const auto& list : owned) {
      long elements = 0;
      for (int p : list) {
        ++seen[p];
        elements += scene.patches[p].element_count();
        biggest = std::max(biggest, scene.patches[p].element_count());
      }
      lo = std::min(lo, elements);
      hi = std::max(hi, elements);
      EXPECT_TRUE(std::is_sorted(list.begin(), list.end()));
    }
    EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int n) { return n == 1; }));
    // Greedy largest-first: no processor exceeds another by more than one patch's elements.
    EXPECT_LE(hi - lo, biggest) << "R=" << R;
  }
}

// Section 4's rule as written: largest patches first, each to the processor with the fewest
// elements so far, ties to the lower rank (a scan of every processor per patch).
std::vector<std::vector<int>> greedy_by_scan(const Scene& scene, int processors) {
  std::vector<int> by_size(scene.patches.size());
  for (int i = 0; i < int(by_size.size()); ++i) by_size[std::size_t(i)] = i;
  std::stable_sort(by_size.begin(), by_size.end(), [&](int a, int b) {
    return scene.patches[a].element_count() > scene.patches[b].element_count();
  });
  std::vector<std::vector<int>> owned(static_cast<std::size_t>(processors));
  std::vector<long> load(static_cast<std::size_t>(processors), 0);
  for (int patch : by_size) {
    int target = 0;
    for (int rank = 1; rank < processors; ++rank)
      if (load[std::size_t(rank)] < load[std::size_t(target)]) target = rank;
    owned[std::size_t(target)].push_back(patch);
    load[std::size_t(target)] += scene.patches[patch].element_count();
  }
  for (auto& list : owned) std::sort(list.begin(), list.end());
  return owned;
}

TEST(Partition, IsTheGreedyRuleWithTiesToTheLowerRank) {
  // Many ties: scene2's patches share a few element counts, and with more processors than
  // patches some stay empty.
  for (const char* name : {"scenes/scene2.json", "scenes/cornell-box.json"}) {
    const Scene scene = load_scene(repo(name));
    for (int R : {1, 3, 8, 64, 1024})
      EXPECT_EQ(partition_patches_by_elements(scene, R), greedy_by_scan(scene, R)) << name << " R=" << R;
  }
}

TEST(Partition, VisibilitySharesSplitAllPatchesEvenly) {
  const Scene scene = load_scene(repo("scenes/scene1.json"));  // 288 patches
  for (int V : {1, 7, 11, 15}) {
    std::size_t total = 0, lo = 1 << 30, hi = 0;
    int expected_first = 0;
    for (int j = 0; j < V; ++j) {
      const auto share = visibility_share(scene, V, j);
      ASSERT_FALSE(share.empty());
      EXPECT_EQ(share.front(), expected_first);
      expected_first = share.back() + 1;
      total += share.size();
      lo = std::min(lo, share.size());
      hi = std::max(hi, share.size());
    }
    EXPECT_EQ(total, scene.patches.size());
    EXPECT_LE(hi - lo, 1u);
  }
}

// Section 5: scene3 does not fit with R=4, V=15 ("not enough memory for elements"), but does
// with R=5, V=11 and with R=64, V=0.
bool fits(const Scene& scene, int R, int V) {
  const PlatformConfig platform = load_platform_config(repo("platforms/ncube2.json"));
  const CostModel costs = load_cost_model(repo("platforms/cost_model.json"));
  ProgramOptions options;
  options.options.samples = 16;  // M = 16, as when it was the default
  const ProgramSetup setup{scene, Placement{R, V}, options, 1.0};
  const auto memory = plan_memory(setup, partition_patches_by_elements(scene, R), costs);
  return std::all_of(memory.begin(), memory.end(),
                     [&](const NodeMemory& m) { return m.bytes <= platform.node_memory; });
}

TEST(MemoryPlan, Scene3FitsAsThePaperReports) {
  const Scene scene = load_scene(repo("scenes/scene3.json"));
  EXPECT_FALSE(fits(scene, 4, 15));
  EXPECT_TRUE(fits(scene, 5, 11));
  EXPECT_TRUE(fits(scene, 64, 0));
  EXPECT_TRUE(fits(scene, 8, 7));
  EXPECT_TRUE(fits(scene, 16, 3));
}

TEST(MemoryPlan, AllPaperConfigurationsOfScenes1And2Fit) {
  for (const char* name : {"scenes/scene1.json", "scenes/scene2.json"}) {
    const Scene scene = load_scene(repo(name));
    for (auto [R, V] : std::vector<std::pair<int, int>>{
             {4, 0}, {8, 0}, {16, 0}, {32, 0}, {64, 0}, {4, 1}, {4, 3}, {4, 7}, {4, 15}, {8, 7}})
      EXPECT_TRUE(fits(scene, R, V)) << name << " R=" << R << " V=" << V;
  }
}

}  // namespace
}  // namespace ncube

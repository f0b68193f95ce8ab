// A node's memory as it runs (src/nodes/node_runtime.h): how many more records fit, worked
// out by hand at the edges (sections 4.1, 4.2: a radiosity processor cuts elements only into
// the memory it has left).
#include "nodes/node_runtime.h"

#include <gtest/gtest.h>

namespace ncube {
namespace {

TEST(NodeRuntime, RecordsThatFitCountWholeRecordsOfTheMemoryLeft) {
  PlatformConfig platform;
  platform.node_memory = 1000;
  const CostModel costs;
  NodeRuntime node(0, NodeRole::kRadiosity, 0, platform, costs, nullptr);
  node.set_memory(600);                       // 400 bytes left
  EXPECT_EQ(node.records_that_fit(100), 4);   // exactly 4 records of 100
  EXPECT_EQ(node.records_that_fit(99), 4);    // 4 x 99 = 396, a fifth would need 495
  EXPECT_EQ(node.records_that_fit(101), 3);   // 4 x 101 = 404 > 400
  EXPECT_EQ(node.records_that_fit(400), 1);
  EXPECT_EQ(node.records_that_fit(401), 0);
  node.change_memory(1);                      // 399 left: one record of 100 fewer
  EXPECT_EQ(node.records_that_fit(100), 3);
  node.set_memory(1000);                      // full: none
  EXPECT_EQ(node.records_that_fit(1), 0);
  node.set_memory(1200);                      // over (it never is, but never negative)
  EXPECT_EQ(node.records_that_fit(100), 0);
}

}  // namespace
}  // namespace ncube

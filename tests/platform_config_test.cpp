// The nCube2 family of platforms/: ncube2-d7.json .. ncube2-d13.json (128 to 8,192 nodes) are
// the 64-node machine of ncube2.json with only the dimension changed.
#include <gtest/gtest.h>

#include <string>

#include "machine/machine_parameters.h"
#include "machine/platform_config.h"

namespace ncube {
namespace {

PlatformConfig shipped(const std::string& file) {
  return load_platform_config(std::string(NCUBE_SOURCE_DIR) + "/platforms/" + file);
}

TEST(PlatformFamily, EachDimensionFrom7To13DiffersFromTheNcube2OnlyInItsDimension) {
  const PlatformConfig base = shipped("ncube2.json");
  EXPECT_EQ(base.dimension, 6);
  for (int d = 7; d <= 13; ++d) {
    const PlatformConfig p = shipped("ncube2-d" + std::to_string(d) + ".json");
    EXPECT_EQ(p.dimension, d);
    EXPECT_EQ(p.node_count(), 1 << d);
    for (const MachineParameter& m : machine_parameters()) {
      if (std::string(m.name) != "dimension") {
        EXPECT_EQ(m.get(p), m.get(base)) << d << " " << m.name;
      }
    }
    EXPECT_EQ(p.simgrid_config, base.simgrid_config) << d;
  }
  EXPECT_EQ(shipped("ncube2-d13.json").node_count(), 8192);
}

}  // namespace
}  // namespace ncube

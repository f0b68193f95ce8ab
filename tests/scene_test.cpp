// The scene's derived totals (src/scene/scene.h), against values worked out by hand.
#include "scene/scene.h"

#include <gtest/gtest.h>

#include "hand_counted_scene.h"

namespace ncube {
namespace {

// The emitted power that the convergence test compares with (--convergence x it) is
// sum (r + g + b) x area: a light of area 2 emitting (1, 2, 3) gives 12, one of area 0.25
// emitting 4 in each channel gives 3, the floor nothing: 15 (without the areas it would be 18,
// and scene0 would converge in 119 iterations instead of 151).
TEST(Scene, EmittedPowerWeighsEachLightByItsArea) {
  const Vec3 X(1, 0, 0), Z(0, 0, 1);
  Scene s;
  s.name = "two lights";
  s.patches = {hand_counted_patch({0, 2, 0}, 2.0 * X, Z, 0.0, 1, 1),
               hand_counted_patch({3, 2, 0}, 0.5 * X, 0.5 * Z, 4.0, 1, 1),
               hand_counted_patch({0, 0, 0}, Z, 4.0 * X, 0.0, 1, 1)};
  s.patches[0].emission = Rgb(1, 2, 3);
  s.build_elements();
  EXPECT_DOUBLE_EQ(s.patches[0].area, 2.0);
  EXPECT_DOUBLE_EQ(s.patches[1].area, 0.25);
  EXPECT_DOUBLE_EQ(s.emitted_power(), 15.0);
}

}  // namespace
}  // namespace ncube

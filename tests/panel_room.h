// Test helper: a room whose blockers cross rays within a fraction of a pad of their ends,
// the parts of a ray Embree is not asked about (embree_scene.h): only the exact test of the
// patches near the ends can find them.
//
// z up. Patch 0: the floor (|x|, |y| <= 1, z = 0). Patch 1: a light in the ceiling
// (x in [0.5, 0.9], |y| <= 0.2, z = 1, facing down), the shooter. Patch 2: a thin panel
// standing on the floor (x = 0, |y| <= 0.2, z in [0, 0.4]). Patch 3: a panel hanging from the
// ceiling along the light's far edge (x = 0.9, |y| <= 0.2, z in [0.6, 1]). The coordinates'
// scale S is 1 + the diagonal 3 = 4, so the pad (SceneBlockers::kPad S = 2e-4 S) is 8e-4 and
// Embree is asked about each ray from half a pad after its start to half a pad before its end.
//
// From the floor point just before the standing panel, (-1e-4, 0, 0), the rays to the light
// points (0.6, 0, 1) and (0.7, 0.1, 1) cross the panel at t = 1e-4 / 0.6001 and
// 1e-4 / 0.7001 (z of the same size, inside the panel): 1.95e-4 and 1.7e-4 from their start,
// a quarter of a pad. The ray to (-0.6, 0, 1) leads away from both panels: unblocked.
//
// From the floor point (0.98, 0, 0), the rays to the light points (0.9 - 1e-5, 0, 1) and
// (0.9 - 1e-5, 0.1, 1) cross the hanging panel's plane x = 0.9 at 1e-5 / 0.08001 of their
// length (about 1.3e-4, a sixth of a pad) before their end, at z = 1 - 1.25e-4 and
// |y| < 0.1: inside the panel. The ray to (0.7, 0, 1) crosses x = 0.9 at z = 0.29, below
// the panel: unblocked.
#pragma once

#include <array>
#include <vector>

#include "host/scene_blockers.h"
#include "scene/scene.h"

namespace ncube {

inline Scene panel_room() {
  Scene scene;
  scene.name = "panel room";
  auto add = [&](const Polygon& polygon, const Rgb& emission) {
    Patch p;
    p.polygon = polygon;
    p.reflectance = Rgb(0.5);
    p.emission = emission;
    scene.patches.push_back(p);
  };
  add(Polygon::quad({-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}), Rgb(0.0));
  add(Polygon::quad({0.5, -0.2, 1}, {0.5, 0.2, 1}, {0.9, 0.2, 1}, {0.9, -0.2, 1}), Rgb(1.0));
  add(Polygon::quad({0, -0.2, 0}, {0, 0.2, 0}, {0, 0.2, 0.4}, {0, -0.2, 0.4}), Rgb(0.0));
  add(Polygon::quad({0.9, -0.2, 0.6}, {0.9, 0.2, 0.6}, {0.9, 0.2, 1}, {0.9, -0.2, 1}), Rgb(0.0));
  scene.build_elements();
  return scene;
}

constexpr int kPanelRoomFloor = 0, kPanelRoomLight = 1, kPanelRoomStanding = 2,
              kPanelRoomHanging = 3;
// The pad a run uses on this room (scale 4).
constexpr double kPanelRoomPad = SceneBlockers::kPad * 4.0;

// A receiving point on the floor, three ray targets on the light, and the rays blocked (by
// the panel given).
struct PanelRoomCase {
  Vec3 point;
  std::array<Vec3, 3> targets;
  unsigned blocked_rays;  // bit k: ray k is blocked
  int blocker;
};

inline std::vector<PanelRoomCase> panel_room_cases() {
  return {
      {{-1e-4, 0, 0}, {{{0.6, 0, 1}, {0.7, 0.1, 1}, {-0.6, 0, 1}}}, 0b011, kPanelRoomStanding},
      {{0.98, 0, 0}, {{{0.9 - 1e-5, 0, 1}, {0.9 - 1e-5, 0.1, 1}, {0.7, 0, 1}}}, 0b011,
       kPanelRoomHanging},
  };
}

}  // namespace ncube

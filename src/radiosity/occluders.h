// The patches a node intersects visibility rays with: all patches of the scene on a node
// without visibility processors (section 2.2), a 1/V share on a visibility processor
// (section 3). The paper's program tests each ray against every patch of the set; the host
// finds the same answers faster with a bounding-volume hierarchy, and counts the tests the
// brute-force loop would have made.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "radiosity/shooter.h"
#include "radiosity/work_counts.h"

namespace ncube {

// How far the brute-force loop runs for one ray (a model choice the paper leaves open).
enum class RayTestPolicy {
  kTestAllPatches,        // "each ray is intersected with all other patches" (default)
  kStopAtFirstBlocker,    // the loop ends at the first patch, in set order, that blocks
};

class Occluders {
 public:
  // `patch_indices` are scene patch indices in the order the brute-force loop visits them.
  Occluders(const Scene& scene, std::vector<int> patch_indices, RayTestPolicy policy);

  // Bit p of the result is set when the segment from `point` to the shooter's part p crosses
  // none of this set's patches other than `receiver_patch` and the shooter itself. Adds the
  // rays, the ray-patch tests and the plane crossings of the brute-force loop to `counts`.
  // A test is a plane crossing when the ray's two ends lie strictly on opposite sides of the
  // patch's plane: only then does the loop go on to the hit point and the edge tests.
  PartMask unblocked_parts(const Vec3& point, int receiver_patch, const Shooter& shooter,
                           WorkCounts& counts) const;

  // The literal brute-force loop (reference for tests): same answers, same counts.
  PartMask unblocked_parts_brute_force(const Vec3& point, int receiver_patch,
                                       const Shooter& shooter, WorkCounts& counts) const;

  int size() const { return int(patches_.size()); }

  struct Candidate {  // one patch, with what the exact segment test needs
    Vec3 vertices[4];
    int vertex_count;
    Vec3 normal;
    double plane_offset;  // normal . x for points x of the plane
    int scene_index;
    Vec3 lo, hi;          // padded bounding box, for the hierarchy only
  };

 private:
  struct Node {
    Vec3 lo, hi;
    int first;         // leaf: first slot in order_; inner: index of the left child
    int count;         // leaf: number of candidates (> 0); inner: 0
    int right;         // inner: index of the right child
    int min_position;  // smallest candidate position in the subtree (for first-blocker order)
  };

  int build(int first, int count);
  // Depth-first over the nodes whose boxes the segment meets; `skip(node)` prunes a subtree,
  // `visit(position)` sees each candidate of a reached leaf and returns true to stop.
  template <class Skip, class Visit>
  void walk(const Vec3& from, const Vec3& delta, Skip skip, Visit visit) const;
  // Position of the first blocking candidate in brute-force order, or -1. `hint` is a
  // candidate position to try first (the previous ray's blocker) or -1.
  int first_blocker(const Vec3& from, const Vec3& delta, int receiver, int shooter,
                    int hint) const;
  // Position of some blocking candidate, or -1.
  int any_blocker(const Vec3& from, const Vec3& delta, int receiver, int shooter,
                  int hint) const;
  // Which side of each candidate's plane the shooter's ray targets lie on. The targets
  // depend only on the shooter's geometry and M, so the last shooter's sides are kept.
  struct TargetSides {
    int part_count = -1;
    std::array<Vec3, kMaxShooterParts> targets{};
    std::vector<std::int32_t> in_front, behind;  // per candidate: targets strictly on each side
    std::vector<std::int8_t> side;               // per candidate and part: +1, -1 or 0
  };
  const TargetSides& target_sides(const Shooter& shooter) const;
  // +1, -1 or 0 (within the tolerance) for a point and the plane of candidate `position`.
  int plane_side(int position, const Vec3& x) const;
  // Plane crossings of the rays from `point` to every target, over the whole set.
  std::uint64_t plane_crossings(const Vec3& point, const TargetSides& sides, int receiver_position,
                                int shooter_position) const;
  int position_in_set(int scene_patch) const {
    return scene_patch >= 0 && scene_patch < int(position_of_scene_patch_.size())
               ? position_of_scene_patch_[scene_patch]
               : -1;
  }

  RayTestPolicy policy_;
  std::vector<Candidate> patches_;  // in brute-force order (position = index)
  // The candidates' planes, one array per coordinate: the crossing count streams through them.
  std::vector<double> plane_x_, plane_y_, plane_z_, plane_offset_;
  double side_tolerance_ = 0.0;     // distances within this count as "on the plane"
  mutable TargetSides sides_;       // of the last shooter (actors run one at a time)
  std::vector<int> order_;          // candidate positions, permuted by the hierarchy
  std::vector<Node> nodes_;
  std::vector<int> position_of_scene_patch_;  // -1 when not in this set
};

// The exact ray-patch test shared by the brute-force loop and the hierarchy: does the
// segment from + t * delta, t in (eps, 1 - eps), cross the candidate's polygon?
bool segment_crosses(const Occluders::Candidate& c, const Vec3& from, const Vec3& delta);

}  // namespace ncube

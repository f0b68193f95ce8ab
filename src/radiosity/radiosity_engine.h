// Progressive-refinement radiosity over patches (shooters) and elements (receivers), paper
// sections 1.1, 2.2 and 4, for the patches one radiosity processor owns. The node programs
// drive it step by step; `run_progressive` drives it alone on the host.
#pragma once

#include <vector>

#include "radiosity/element_store.h"
#include "radiosity/occluders.h"
#include "radiosity/shooter.h"
#include "radiosity/subdivision.h"
#include "radiosity/work_counts.h"

namespace ncube {

struct ShooterChoice {
  int patch = -1;      // -1: no candidate
  double power = 0.0;  // unshot power (r+g+b) * area
  Rgb unshot{0.0};     // unshot radiosity

  // The better of two candidates: more power, ties to the lower patch index, so that every
  // partition of the patches picks the same shooter as the sequential program.
  bool better_than(const ShooterChoice& other) const {
    if (patch < 0) return false;
    if (other.patch < 0) return true;
    return power > other.power || (power == other.power && patch < other.patch);
  }
};

class RadiosityEngine {
 public:
  RadiosityEngine(const Scene& scene, const std::vector<int>& owned_patches);

  // Step 1 of section 2.2: the held patch with the most unshot power.
  ShooterChoice best_shooter(WorkCounts& counts) const;
  // The held elements that receive from the shooter: all but the shooter's own, and with
  // `skip_facing_away` only those that can see its front (the others get no rays; their
  // form factor is zero anyway). In store order.
  std::vector<ElementRef> receivers(const Shooter& shooter, bool skip_facing_away,
                                    WorkCounts& counts) const;
  // The receivers' visibility points (element centres) and their patches.
  void visibility_points(const std::vector<ElementRef>& receivers, std::vector<Vec3>& points,
                         std::vector<int>& patches) const;
  // Adds the shooter's light to each receiver through the parts its mask marks visible:
  // form factor = sum of the point-to-part contour integrals (section 2.2). The form factors
  // are computed on `threads` host threads, the light is added in receiver order, so the
  // result does not depend on `threads`.
  // `form_factors`, when given, are the receivers' receiver_form_factor values computed
  // beforehand (by the host threads computing ahead, lookahead.h).
  void gather(const Shooter& shooter, const std::vector<ElementRef>& receivers,
              const std::vector<PartMask>& masks, WorkCounts& counts, int threads = 1,
              const double* form_factors = nullptr);
  // Section 4.1, after the shot's light has been distributed: tests the elements that have
  // just received it and cuts those whose corner radiosities differ too much. A cut
  // element's children start from its radiosity before this shot (its share of the shot is
  // taken back from the patch's unshot radiosity too) and are returned, in store order, to
  // receive the current shot at their own centres. At most `room` new element records are
  // made (4 per cut, docs/model.md); when more were wanted, `out_of_room` is set.
  std::vector<ElementRef> subdivide(const std::vector<ElementRef>& shot,
                                    const SubdivisionOptions& options, long room,
                                    bool& out_of_room, WorkCounts& counts);
  // The shooter's owner forgets the radiosity it has just shot.
  void clear_unshot(int patch);

  const Scene& scene() const { return store_.scene(); }
  ElementStore& store() { return store_; }
  const ElementStore& store() const { return store_; }
  bool holds(int patch) const { return store_.holds(patch); }
  const Rgb& unshot(int patch) const;  // of a held patch
  Rgb patch_radiosity(int patch) const;  // of a held patch: area-weighted mean of its elements
  // The radiosity of the scene's element e (Scene::elements) while its patch is not cut.
  const Rgb& element_radiosity(int e) const;

 private:
  ElementStore store_;
};

struct ProgressiveOptions {
  int samples = 16;                    // M, parts of the shooter
  RayTestPolicy ray_policy = RayTestPolicy::kTestAllPatches;
  VisibilityMethod visibility = VisibilityMethod::kBruteForce;  // --visibility (section 6)
  bool skip_facing_away = false;       // true: receivers that cannot see the shooter trace no rays
  double convergence_fraction = 1e-4;  // stop when max unshot power < this x emitted power
  int max_iterations = -1;             // -1: until converged
  int host_threads = 0;                // host threads per compute step (0: all cores); no
                                       // effect on any result, only on host time
  SubdivisionOptions subdivision;      // section 4.1, off by default
};

struct ProgressiveRun {
  int iterations = 0;
  bool converged = false;
  std::vector<int> shooters;         // patch shot in each iteration
  std::vector<long> elements;        // elements held after each iteration
  std::vector<WorkCounts> per_iteration;
  WorkCounts total;
};

// The form factor from a receiving element (centre, unit normal) to the shooter's parts in
// `mask`: zero behind the shooter's plane (it emits from its front only).
double receiver_form_factor(const Shooter& shooter, const Vec3& centre, const Vec3& normal,
                            PartMask mask);

// Whether the best remaining shooter is weak enough to stop.
bool has_converged(const ShooterChoice& best, double emitted_power, double fraction);

// The visible parts of the shooter from each receiving element's centre (one mask per
// receiver, in order), on `threads` host threads; adds the brute-force counts.
std::vector<PartMask> visible_parts(const RadiosityEngine& engine, const Occluders& occluders,
                                    const std::vector<ElementRef>& receivers,
                                    const Shooter& shooter, WorkCounts& counts, int threads);

// The whole solution on the host, one processor, brute-force-equivalent visibility.
ProgressiveRun run_progressive(RadiosityEngine& engine, const Occluders& occluders,
                               const ProgressiveOptions& options);

}  // namespace ncube

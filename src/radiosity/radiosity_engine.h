// Progressive-refinement radiosity over patches (shooters) and elements (receivers), paper
// sections 1.1, 2.2 and 4, for the patches one radiosity processor owns. The node programs
// drive it step by step; `run_progressive` drives it alone on the host.
#pragma once

#include <vector>

#include "radiosity/occluders.h"
#include "radiosity/shooter.h"
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
  RadiosityEngine(const Scene& scene, std::vector<int> owned_patches);

  // Step 1 of section 2.2: the owned patch with the most unshot power.
  ShooterChoice best_shooter(WorkCounts& counts) const;
  // The owned elements that receive from the shooter: all but the shooter's own, and with
  // `skip_facing_away` only those that can see its front (the others get no rays; their
  // form factor is zero anyway).
  std::vector<int> receivers(const Shooter& shooter, bool skip_facing_away,
                             WorkCounts& counts) const;
  // Adds the shooter's light to each receiver through the parts its mask marks visible:
  // form factor = sum of the point-to-part contour integrals (section 2.2). The form factors
  // are computed on `threads` host threads, the light is added in receiver order, so the
  // result does not depend on `threads`.
  void gather(const Shooter& shooter, const std::vector<int>& receivers,
              const std::vector<PartMask>& masks, WorkCounts& counts, int threads = 1);
  // The shooter's owner forgets the radiosity it has just shot.
  void clear_unshot(int patch) { unshot_[patch] = Rgb(0.0); }

  const Scene& scene() const { return scene_; }
  const std::vector<int>& owned_patches() const { return owned_; }
  const std::vector<int>& owned_elements() const { return owned_elements_; }
  const Rgb& element_radiosity(int element) const { return radiosity_[element]; }
  const Rgb& unshot(int patch) const { return unshot_[patch]; }
  Rgb patch_radiosity(int patch) const;  // area-weighted mean of its elements

 private:
  const Scene& scene_;
  std::vector<int> owned_;
  std::vector<int> owned_elements_;
  std::vector<Rgb> radiosity_;  // per scene element (meaningful for owned ones)
  std::vector<Rgb> unshot_;     // per scene patch (meaningful for owned ones)
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
};

struct ProgressiveRun {
  int iterations = 0;
  bool converged = false;
  std::vector<int> shooters;         // patch shot in each iteration
  std::vector<WorkCounts> per_iteration;
  WorkCounts total;
};

// Whether the best remaining shooter is weak enough to stop.
bool has_converged(const ShooterChoice& best, double emitted_power, double fraction);

// The visible parts of the shooter from each receiving element's centre (one mask per
// receiver, in order), on `threads` host threads; adds the brute-force counts.
std::vector<PartMask> visible_parts(const Scene& scene, const Occluders& occluders,
                                    const std::vector<int>& receivers, const Shooter& shooter,
                                    WorkCounts& counts, int threads);

// The whole solution on the host, one processor, brute-force-equivalent visibility.
ProgressiveRun run_progressive(RadiosityEngine& engine, const Occluders& occluders,
                               const ProgressiveOptions& options);

}  // namespace ncube

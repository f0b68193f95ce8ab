// Progressive-refinement radiosity over patches (shooters) and elements (receivers), paper
// sections 1.1, 2.2 and 4, for the patches one radiosity processor owns. The node programs
// drive it step by step; `run_progressive` drives it alone on the host.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "counts/work_counts.h"
#include "radiosity/element_store.h"
#include "radiosity/hemicube.h"
#include "radiosity/host_assist.h"
#include "radiosity/subdivision.h"
#include "visibility/occluder_set.h"
#include "visibility/shooter.h"

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

// The receivers' visibility points cut into the blocks a radiosity processor sends its
// visibility processors (section 3: "blocks of e.g. 100").
struct PointBlocks {
  std::vector<Vec3> points;
  std::vector<int> patches;  // the patch each point lies on
  int block_size = 1;
  std::shared_ptr<HostAssist::PostedShot> posted;  // the host's handle on them (may be null)

  int count() const { return int((points.size() + std::size_t(block_size) - 1) / std::size_t(block_size)); }
  std::size_t first(int block) const { return std::size_t(block) * std::size_t(block_size); }
  std::size_t end(int block) const { return std::min(points.size(), first(block + 1)); }
  PointBlock block(int b) const { return PointBlock(points, patches).part(first(b), end(b)); }
};

class RadiosityEngine {
 public:
  RadiosityEngine(const Scene& scene, const std::vector<int>& owned_patches);

  // The host's help (host_assist.h; not owned; null: none) for radiosity processor `rank`.
  void use_host_assist(HostAssist* assist, int rank);

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
  // The same cut into blocks of `block_size` for the visibility processors (section 3).
  PointBlocks point_blocks(const Shooter& shooter, const std::vector<ElementRef>& receivers,
                           int block_size) const;
  // Adds the shooter's light to each receiver through the parts its mask marks visible:
  // form factor = sum of the point-to-part contour integrals (section 2.2). The light is
  // added in receiver order.
  void gather(const Shooter& shooter, const std::vector<ElementRef>& receivers,
              const std::vector<PartMask>& masks, WorkCounts& counts);
  // The same for block `block` of `blocks` (made from `receivers`), `masks` its answers.
  void gather_block(const Shooter& shooter, const std::vector<ElementRef>& receivers,
                    const PointBlocks& blocks, int block, const std::vector<PartMask>& masks,
                    WorkCounts& counts);
  // The receivers' form factors (receiver_form_factor) to the shooter's parts their masks
  // mark visible, in receiver order: remembered from an earlier shot with the same question,
  // or computed (on the host's threads; host_assist.h). Adds no light and counts nothing.
  std::vector<double> form_factors(const Shooter& shooter, const std::vector<ElementRef>& receivers,
                                   const std::vector<PartMask>& masks);
  // Adds the shooter's light to each receiver through its form factor to the shooter,
  // form_factors[k] for receivers[k], computed by another method (the hemicube); the light is
  // added in receiver order, as gather adds it.
  void gather_form_factors(const Shooter& shooter, const std::vector<ElementRef>& receivers,
                           const std::vector<double>& form_factors, WorkCounts& counts);
  // Section 4.1, after the shot's light has been distributed: tests the elements that have
  // just received it and cuts those whose corner radiosities differ too much. A cut
  // element's children start from its radiosity before this shot (its share of the shot is
  // taken back from the patch's unshot radiosity too) and are returned, in store order, to
  // receive the current shot at their own centres. At most `room` new element records are
  // made (4 per cut, docs/model.md); when more were wanted, `out_of_room` is set.
  std::vector<ElementRef> subdivide(const std::vector<ElementRef>& shot,
                                    const SubdivisionOptions& options, long room,
                                    bool& out_of_room, WorkCounts& counts);
  // After shooting `patch`: its holder forgets the radiosity it has just shot.
  void finish_shot(int patch);

  const Scene& scene() const { return store_.scene(); }
  ElementStore& store() { return store_; }
  const ElementStore& store() const { return store_; }
  bool holds(int patch) const { return store_.holds(patch); }
  const Rgb& unshot(int patch) const;  // of a held patch
  Rgb patch_radiosity(int patch) const;  // of a held patch: area-weighted mean of its elements
  // The radiosity of the scene's element e (Scene::elements) while its patch is not cut.
  const Rgb& element_radiosity(int e) const;

 private:
  // gather's work; `form_factors`: the receivers' receiver_form_factor values computed
  // beforehand (by the host, host_assist.h), or null.
  void add_light(const Shooter& shooter, const std::vector<ElementRef>& receivers,
                 const std::vector<PartMask>& masks, const double* form_factors,
                 WorkCounts& counts);

  // Receiver `ref` gains the shooter's light through form factor `form_factor`.
  void receive(const Shooter& shooter, const ElementRef& ref, double form_factor, WorkCounts& counts);

  ElementStore store_;
  HostAssist* assist_ = nullptr;
};

struct ProgressiveOptions {
  int samples = 64;                    // M, parts of the shooter (the calibrated setup,
                                       // docs/reproduce.md; simulate's default)
  RayTestPolicy ray_policy = RayTestPolicy::kTestAllPatches;
  std::string visibility = "brute-force";  // --visibility: a name in visibility_methods()
                                          // (visibility/visibility_methods.h; section 6)
  std::string form_factors = "ray-traced";  // --form-factors: a name in form_factor_methods()
                                           // (radiosity/form_factor_methods.h)
  HemicubeOptions hemicube;                // --hemicube-resolution, --hemicube-placement
  bool skip_facing_away = false;       // true: receivers that cannot see the shooter trace no rays
  double convergence_fraction = 1e-4;  // stop when max unshot power < this x emitted power
  int max_iterations = -1;             // -1: until converged
  int host_threads = 0;                // host threads per compute step (0: all cores); no
                                       // effect on any result, only on host time
  bool reference_visibility = false;   // the readable definitions alone (occluder_set.h): no
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
// receiver, in order); adds the set's counts.
std::vector<PartMask> visible_parts(const RadiosityEngine& engine, const OccluderSet& occluders,
                                    const std::vector<ElementRef>& receivers,
                                    const Shooter& shooter, WorkCounts& counts);

// The whole solution on the host, one processor, without the simulated machine.
ProgressiveRun run_progressive(RadiosityEngine& engine, const OccluderSet& occluders,
                               const ProgressiveOptions& options);

}  // namespace ncube

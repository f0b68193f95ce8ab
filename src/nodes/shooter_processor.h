// A node of the shooter-centred scheme the paper contrasts itself with (sections 2.2 and 6;
// --parallelisation shooters; docs/model.md, "The shooter-centred scheme"): every node holds
// the whole scene and every element's radiosity and unshot radiosity. Each iteration every
// node chooses the same S shooters (the patches with the most unshot power, S one per node
// by default), node k shoots the k-th of them to every element with the run's form-factor
// method into a vector of radiosity increments, and the vectors are summed on every node
// through the network (nodes/increment_exchange.h): the distribution of radiosity values
// after the form-factor calculation that the paper's receiver-centred program avoids. Then
// each node adds the sum to its radiosities and unshot radiosities, the shot patches'
// unshot radiosity having been cleared first.
#pragma once

#include <vector>

#include "nodes/increment_exchange.h"
#include "nodes/node_runtime.h"
#include "nodes/program_setup.h"
#include "visibility/occluder_set.h"

namespace ncube {

// One shooter's light to every element `engine` holds, shot by the run's form-factor method
// over the whole scene, as increments by scene element (increments[e] = rho_e F(e -> s) x
// unshot; the elements it does not reach keep theirs); the work is charged to `runtime`.
// Both shooter-centred schemes shoot with it (this one and nodes/circulation_processor.h),
// so that their physics is the same to the last bit.
void shoot_to_scene(const ProgramSetup& setup, RadiosityEngine& engine, const OccluderSet& occluders,
                    const ShooterChoice& choice, std::vector<Rgb>& increments, NodeRuntime& runtime);

class ShooterProcessor {
 public:
  // `engine` holds every patch of the scene; `occluders` is the whole scene.
  ShooterProcessor(const ProgramSetup& setup, int rank, NodeRuntime& runtime,
                   RadiosityEngine& engine, const OccluderSet& occluders);

  void run();  // the actor's body

  // Every node decides the same; these are this node's record. When each iteration ended
  // (the next shooters were chosen), the patches shot (iteration by iteration, in the order
  // of the nodes that shot them), whether the run converged, and the largest unshot power
  // at the last choice.
  const std::vector<double>& iteration_ends() const { return iteration_ends_; }
  const std::vector<int>& shooters() const { return shooters_; }
  bool converged() const { return converged_; }
  double largest_unshot_power() const { return largest_unshot_power_; }

  // The shooters per iteration the options ask for: --shooters-per-iteration, or one per node.
  static int shooters_per_iteration(const ProgramSetup& setup);

 private:
  // The S held patches with the most unshot power, best first (ShooterChoice::better_than),
  // only those with some; one pass over the patches.
  std::vector<ShooterChoice> choose_shooters(WorkCounts& counts) const;
  // The iteration's summed increments added to every element and its patch's unshot
  // radiosity, after the shot patches' unshot radiosity is cleared.
  void apply(const std::vector<ShooterChoice>& shot, const std::vector<Rgb>& increments);

  const ProgramSetup& setup_;
  int rank_;
  NodeRuntime& runtime_;
  RadiosityEngine& engine_;
  const OccluderSet& occluders_;
  IncrementExchange exchange_;
  std::vector<double> iteration_ends_;
  std::vector<int> shooters_;
  bool converged_ = false;
  double largest_unshot_power_ = 0.0;
};

}  // namespace ncube

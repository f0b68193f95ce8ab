// A node of the shooter-centred scheme built from Çapın et al.'s abstracts, held against the paper's (claim 2;
// --parallelisation circulation; docs/model.md, "The circulation opponent"): Çapın, Aykanat &
// Özgüç's parallel progressive refinement on ring-connected and hypercube multicomputers
// (Parallel Rendering Symposium 1993; Computers & Graphics 20(2) 1996: "a parallel
// progressive radiosity algorithm based on patch data circulation"), as far as its abstracts
// say it, the rest assumed and named in docs/model.md:
//   - static task assignment: every node owns a fixed share of the patches and holds their
//     radiosity data and elements only (assumed: the paper's partition by elements, so that
//     both programs get the same shares);
//   - synchronous, several patches shoot their energy at a time: every node's best patch is
//     a candidate, the candidates circulate round the ring, and every node shoots its own
//     candidate when it is among the S best (S = --shooters-per-iteration, all R by default);
//   - the shooter's form factors to every element of the scene (shooter-centred: the run's
//     form-factor method over the whole scene, whose geometry every node holds, assumed);
//   - the light distribution by a global circulation: the increments for each node's
//     elements go once round the ring, every node adding its shooter's light
//     (nodes/ring_circulation.h), so that each node receives only the sums for its own
//     elements; then every node adds them to its elements and patches.
#pragma once

#include <vector>

#include "nodes/node_runtime.h"
#include "nodes/program_setup.h"
#include "nodes/ring_circulation.h"
#include "visibility/occluder_set.h"

namespace ncube {

class CirculationProcessor {
 public:
  // `engine` holds every patch of the scene (for the form factors); this node owns, and keeps
  // the radiosities of, owned[rank] only. `occluders` is the whole scene.
  CirculationProcessor(const ProgramSetup& setup, int rank,
                       const std::vector<std::vector<int>>& owned, NodeRuntime& runtime,
                       RadiosityEngine& engine, const OccluderSet& occluders);

  void run();  // the actor's body

  // Every node decides the same; these are this node's record (as ShooterProcessor's).
  const std::vector<double>& iteration_ends() const { return iteration_ends_; }
  const std::vector<int>& shooters() const { return shooters_; }
  bool converged() const { return converged_; }
  double largest_unshot_power() const { return largest_unshot_power_; }
  const std::vector<int>& owned() const { return owned_; }

 private:
  // The owned patch with the most unshot power (none if no owned patch has any).
  ShooterChoice local_best(WorkCounts& counts) const;
  // The iteration's shooters: the S best of the candidates with something to shoot, best first.
  std::vector<ShooterChoice> choose(std::vector<ShooterChoice> candidates) const;
  // The sums for this node's elements added to them and their patches' unshot radiosity,
  // after this node's shot patch (if any) has had its unshot radiosity cleared.
  void apply(const std::vector<ShooterChoice>& shot, const std::vector<Rgb>& block);

  const ProgramSetup& setup_;
  int rank_;
  NodeRuntime& runtime_;
  RadiosityEngine& engine_;
  const OccluderSet& occluders_;
  std::vector<int> owned_;
  std::vector<int> owned_slots_;  // each owned patch's slot in the engine's store
  RingCirculation ring_;
  std::vector<double> iteration_ends_;
  std::vector<int> shooters_;
  bool converged_ = false;
  double largest_unshot_power_ = 0.0;
};

// Each rank's elements as scene element indices, in the order of its owned patches.
std::vector<std::vector<std::size_t>> owned_element_blocks(const Scene& scene,
                                                           const std::vector<std::vector<int>>& owned);

}  // namespace ncube

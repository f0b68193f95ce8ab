// A radiosity processor (paper sections 2.2, 3 and 4): owns a set of patches with their
// elements. Every iteration it offers its best patch, learns the shooter chosen by the
// master, and shoots it to its own elements: it finds the visible parts of the shooter from
// each element, by tracing the rays itself (V = 0) or by asking its visibility processors
// (V > 0), and adds the light through the form factors of the visible parts.
#pragma once

#include <vector>

#include "nodes/collectives.h"
#include "nodes/node_runtime.h"
#include "nodes/program_setup.h"

namespace ncube {

class RadiosityProcessor {
 public:
  // `occluders` is the whole scene when V = 0, unused (may be null) when V > 0.
  RadiosityProcessor(const ProgramSetup& setup, int rank, NodeRuntime& runtime,
                     RadiosityEngine& engine, const Occluders* occluders);

  void run();  // the actor's body

  // At the master: when each iteration ended (the next decision was taken).
  const std::vector<double>& iteration_ends() const { return iteration_ends_; }
  const std::vector<int>& shooters() const { return shooters_; }
  bool converged() const { return converged_; }
  // At the master: the largest unshot power at the last decision (for progress reports).
  double largest_unshot_power() const { return largest_unshot_power_; }

 private:
  ShooterChoice decide(const ShooterChoice& global_best);
  void tell_visibility_processors(const ShooterChoice& decision);
  void shoot(const Shooter& shooter);
  void shoot_with_visibility_processors(const Shooter& shooter);
  void send_block(const std::vector<int>& receivers, int block);

  const ProgramSetup& setup_;
  int rank_;
  NodeRuntime& runtime_;
  RadiosityEngine& engine_;
  const Occluders* occluders_;
  ShooterSelection selection_;
  std::vector<double> iteration_ends_;
  std::vector<int> shooters_;
  bool converged_ = false;
  double largest_unshot_power_ = 0.0;
};

}  // namespace ncube

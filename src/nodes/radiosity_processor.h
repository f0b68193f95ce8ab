// A radiosity processor (paper sections 2.2, 3 and 4): holds a set of patches with their
// elements. Every iteration it offers its best patch, learns the shooter chosen by the
// master, and shoots it to its own elements: it finds the visible parts of the shooter from
// each element, by tracing the rays itself (V = 0) or by asking its visibility processors
// (V > 0), and adds the light through the form factors of the visible parts. With adaptive
// subdivision (4.1) it then cuts the elements where the light changes too fast and shoots
// the current shooter to the new ones; with load balancing (4.2) it gives patches to, or
// takes patches from, other radiosity processors as the master orders.
#pragma once

#include <vector>

#include "nodes/collectives.h"
#include "nodes/node_runtime.h"
#include "nodes/program_setup.h"
#include "visibility/occluder_set.h"

namespace ncube {

// At the master: why the run ended out of memory (node -1: it did not).
struct RunOutOfMemory {
  int node = -1;
  double needed_bytes = 0.0;
};

class RadiosityProcessor {
 public:
  // `occluders` is the whole scene when V = 0, unused (may be null) when V > 0.
  RadiosityProcessor(const ProgramSetup& setup, int rank, NodeRuntime& runtime,
                     RadiosityEngine& engine, const OccluderSet* occluders);

  void run();  // the actor's body

  // At the master: when each iteration ended (the next decision was taken).
  const std::vector<double>& iteration_ends() const { return iteration_ends_; }
  const std::vector<int>& shooters() const { return shooters_; }
  bool converged() const { return converged_; }
  const RunOutOfMemory& out_of_memory() const { return out_of_memory_; }
  // At the master: the largest unshot power at the last decision (for progress reports).
  double largest_unshot_power() const { return largest_unshot_power_; }
  // At the master, per iteration: every radiosity processor's elements at its start.
  const std::vector<std::vector<long>>& elements_per_iteration() const { return elements_; }
  // Patches this processor gave away and received (4.2).
  long patches_sent() const { return patches_sent_; }
  // Transfers it carried out as sender (section 4.2): messages and their modeled payload.
  long transfers_sent() const { return transfers_sent_; }
  double transfer_bytes_sent() const { return transfer_bytes_sent_; }
  long patches_received() const { return patches_received_; }

 private:
  // This processor's load for the master (section 4.2), `candidate` being its shooter candidate.
  ProcessorLoad load(int candidate) const;
  Decision decide(const ShooterChoice& global_best, const std::vector<ProcessorLoad>& loads);
  void tell_visibility_processors(const Decision& decision);
  void carry_out(const std::vector<Transfer>& transfers, int shooter);
  void shoot(const Shooter& shooter);
  void find_visible_parts_and_gather(const Shooter& shooter, const std::vector<ElementRef>& receivers);
  void gather_with_visibility_processors(const Shooter& shooter,
                                         const std::vector<ElementRef>& receivers);
  void send_block(const PointBlocks& blocks, int block);
  // Section 4.1: cuts the shot's receivers where the light changes too fast, as far as the
  // node's memory allows; returns the new elements (to receive the same shot).
  std::vector<ElementRef> subdivide(const std::vector<ElementRef>& receivers);
  bool holds_geometry_of_all_patches() const { return setup_.placement.visibility_processors == 0; }

  const ProgramSetup& setup_;
  int rank_;
  NodeRuntime& runtime_;
  RadiosityEngine& engine_;
  const OccluderSet* occluders_;
  ShooterSelection selection_;
  std::vector<double> iteration_ends_;
  std::vector<int> shooters_;
  bool converged_ = false;
  RunOutOfMemory out_of_memory_;
  double largest_unshot_power_ = 0.0;
  std::vector<std::vector<long>> elements_;
  double wanted_bytes_ = 0.0;  // bytes of the cuts the last shot could not make
  long patches_sent_ = 0, patches_received_ = 0;
  long transfers_sent_ = 0;
  double transfer_bytes_sent_ = 0.0;
};

}  // namespace ncube

#include "simulation/host_machinery.h"

#include <functional>
#include <string>

#include "host/fast_occluders.h"
#include "host/fast_octree.h"
#include "host/host_threads.h"
#include "host/lookahead.h"
#include "host/scene_blockers.h"
#include "host/threaded_assist.h"
#include "host/threaded_occluders.h"
#include "radiosity/form_factor_methods.h"
#include "visibility/brute_force_occluders.h"
#include "visibility/octree.h"
#include "visibility/visibility_methods.h"

namespace ncube {

namespace {

// What the host's version of a method builds from.
struct HostSetup {
  const Scene& scene;
  const std::vector<std::vector<int>>& patch_sets;
  const ProgressiveOptions& options;
  int visibility_processors, radiosity_processors, block_size;
  bool loads_change;
  int threads;  // host threads
  bool ahead;   // V > 0 and more than one host thread: blocks answered ahead (lookahead.h)
};

// The host's fast version of a visibility method, registered under the method's name in
// visibility_methods(): the occluder sets answering as the readable definition does (every
// answer and every count the same, bit for bit) and the engines' help.
struct HostVisibilityMethod {
  std::string name;
  std::function<void(HostMachinery&, const HostSetup&)> build;
};

// FastOccluders (Embree, the answer cache), the blocks answered ahead with V > 0.
void build_fast_brute_force(HostMachinery& machinery, const HostSetup& host) {
  const ProgressiveOptions& options = host.options;
  std::vector<FastOccluders*> fast_sets;
  for (const std::vector<int>& patches : host.patch_sets) {
    auto set = std::make_unique<FastOccluders>(host.scene, patches, options.ray_policy,
                                               options.host_threads);
    fast_sets.push_back(set.get());
    machinery.occluders.push_back(std::move(set));
  }
  if (host.ahead) {
    auto lookahead = std::make_unique<Lookahead>(
        host.scene, std::vector<const FastOccluders*>(fast_sets.begin(), fast_sets.end()),
        host.threads - 1);
    for (FastOccluders* share : fast_sets) share->use_lookahead(lookahead.get());
    // Guesses of the next shots need receivers that never change and do not depend on the
    // shooter.
    if (!host.loads_change && !options.skip_facing_away)
      lookahead->guess_shots(options.samples, host.block_size, host.radiosity_processors);
    machinery.assist = std::move(lookahead);
  } else {
    // Choice: the receivers' form factors remembered across shots without visibility
    // processors, where the brute-force set already holds the scene's answer cache (the
    // octree would build the scene's Embree scene for it). With V > 0 on one host thread they
    // are not: 150 iterations of scene3 R=8 V=7 gained nothing and held 130 MB more.
    const bool remember = host.visibility_processors == 0 && !fast_sets.empty();
    machinery.assist = std::make_unique<ThreadedAssist>(
        options.host_threads, remember ? SceneBlockers::for_scene(host.scene) : nullptr);
  }
}

// FastOctree (the walk vectorised), its blocks answered ahead with V > 0, otherwise each
// block's points shared out over the host threads.
void build_fast_octree(HostMachinery& machinery, const HostSetup& host) {
  std::vector<FastOctree*> octree_sets;
  for (const std::vector<int>& patches : host.patch_sets) {
    if (host.ahead) {
      auto set = std::make_unique<FastOctree>(std::make_unique<const Octree>(host.scene, patches));
      octree_sets.push_back(set.get());
      machinery.occluders.push_back(std::move(set));
    } else {
      machinery.occluders.push_back(std::make_unique<const ThreadedOccluders>(
          std::make_unique<const FastOctree>(std::make_unique<const Octree>(host.scene, patches)),
          host.options.host_threads));
    }
  }
  if (host.ahead) {
    auto lookahead = std::make_unique<Lookahead>(
        host.scene, std::vector<const FastOctree*>(octree_sets.begin(), octree_sets.end()),
        host.threads - 1);
    for (FastOctree* share : octree_sets) share->use_lookahead(lookahead.get());
    machinery.assist = std::move(lookahead);  // no guesses: the octree's answers are not kept
  } else {
    machinery.assist = std::make_unique<ThreadedAssist>(host.options.host_threads, nullptr);
  }
}

// One line per method of visibility_methods(), under the same name.
const MethodRegistry<HostVisibilityMethod>& host_visibility_methods() {
  static const MethodRegistry<HostVisibilityMethod> registry(
      "host version of a visibility method",
      {
          {"brute-force", build_fast_brute_force},
          {"octree", build_fast_octree},
      });
  return registry;
}

// The host's version of each form-factor method (radiosity/form_factor_methods.h), under
// the same name: what the host adds to the method's readable definition. The ray-traced form
// factors' help comes with the visibility method's host version above (the answer cache,
// the form factors computed on the host threads or ahead); the hemicube runs as defined, on
// one thread (bench/hemicube_bench.cpp measures it against the rays' host time).
struct HostFormFactorMethod {
  std::string name;
  std::string host_version;
};

// Host versions added from outside the list (add_host_form_factor_method), and whether the
// registry has been read, after which none may be added.
std::vector<HostFormFactorMethod>& added_host_methods() {
  static std::vector<HostFormFactorMethod> added;
  return added;
}

bool& host_registry_read() {
  static bool read = false;
  return read;
}

const MethodRegistry<HostFormFactorMethod>& host_form_factor_methods() {
  static const MethodRegistry<HostFormFactorMethod> registry = [] {
    std::vector<HostFormFactorMethod> methods{
        {"ray-traced", "the visibility method's host version"},
        {"hemicube", "the readable definition"},
    };
    for (HostFormFactorMethod& method : added_host_methods()) methods.push_back(std::move(method));
    host_registry_read() = true;
    return MethodRegistry<HostFormFactorMethod>("host version of a form-factor method",
                                                std::move(methods));
  }();
  return registry;
}

}  // namespace

void add_host_form_factor_method(std::string name, std::string host_version) {
  if (host_registry_read())
    throw std::logic_error("host version of \"" + name + "\" added after the registry was read");
  added_host_methods().push_back({std::move(name), std::move(host_version)});
}

void build_host_machinery(HostMachinery& machinery, const Scene& scene,
                          const std::vector<std::vector<int>>& patch_sets,
                          const ProgressiveOptions& options, int visibility_processors,
                          int radiosity_processors, int block_size, bool loads_change) {
  const VisibilityMethod& method = visibility_methods().at(options.visibility);
  host_form_factor_methods().at(form_factor_methods().at(options.form_factors).name);
  if (options.reference_visibility) {
    // The program computes everything itself, on one thread.
    for (const std::vector<int>& patches : patch_sets)
      machinery.occluders.push_back(method.reference(scene, patches, options.ray_policy));
    return;
  }
  // With visibility processors and more than one host thread, the blocks' answers and form
  // factors are computed ahead on the other threads (lookahead.h).
  const int threads = resolve_host_threads(options.host_threads);
  const HostSetup host{scene,        patch_sets,   options, visibility_processors,
                       radiosity_processors, block_size, loads_change,
                       threads,      visibility_processors > 0 && threads > 1};
  host_visibility_methods().at(method.name).build(machinery, host);
}

}  // namespace ncube

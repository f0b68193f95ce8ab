// The form-factor methods a run can choose (--form-factors), each registered once
// (util/method_registry.h; docs/architecture.md, "How to add a method"): its name (the
// option's value and the result file's config.form_factors), what the docs say of it, and its
// readable definition: how a node that holds the geometry of `occluders`' patches shoots a
// shooter to its receiving elements (their form factors and the light they gain, with the work
// counted), the work a node does once when it starts, and the memory the method needs on a
// node beside the patches and elements. The definition is the host's version too (no host
// machinery changes a hemicube's answers or counts; host_machinery.cpp says so under the same
// name); tests/method_registry_test.cpp checks that every consumer knows every name.
#pragma once

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "counts/held_items.h"
#include "radiosity/radiosity_engine.h"
#include "util/method_registry.h"
#include "visibility/occluder_set.h"

namespace ncube {

struct FormFactorMethod {
  std::string name;
  std::string doc;
  // Shoots `shooter` to `receivers` (held by `engine`, in store order) on a node that holds
  // the geometry of the patches of `occluders` for visibility; adds the work to `counts`.
  std::function<void(RadiosityEngine& engine, const OccluderSet& occluders, const Shooter& shooter,
                     const std::vector<ElementRef>& receivers, const ProgressiveOptions& options,
                     WorkCounts& counts)>
      shoot;
  // The same shot's form factors only, receivers[k]'s at k, with the work counted but no
  // light added: for a node program that adds the light itself (nodes/shooter_processor.cpp).
  std::function<std::vector<double>(RadiosityEngine& engine, const OccluderSet& occluders,
                                    const Shooter& shooter, const std::vector<ElementRef>& receivers,
                                    const ProgressiveOptions& options, WorkCounts& counts)>
      form_factors;
  // With visibility processors (V > 0, section 3): adds the light of block `block` of
  // `blocks` (made from `receivers`), `masks` the AND of the V answers for its receivers.
  // Empty when the method is not defined with visibility processors: such a run is refused
  // (exit 2) with `without_visibility_processors` as the reason.
  std::function<void(RadiosityEngine& engine, const Shooter& shooter,
                     const std::vector<ElementRef>& receivers, const PointBlocks& blocks, int block,
                     const std::vector<PartMask>& masks, WorkCounts& counts)>
      gather_visible;
  std::string without_visibility_processors;
  // The work of a node that computes form factors, once when it starts (none: all zero).
  std::function<WorkCounts(const ProgressiveOptions& options)> setup_work;
  // What such a node holds beyond its patches and elements, in items the cost model weighs.
  std::function<HeldItems(const ProgressiveOptions& options)> node_items;
  // Whether it traces the rays the rays' options shape (--visibility, --ray-test, --samples);
  // if not, those options are refused away from their defaults (exit 2).
  bool traces_rays = true;
  // Its own options, by their result-file fields: recorded for its runs only. Those set away
  // from their defaults, as "--flag value" (empty function: it has none), are refused with
  // any other method; `refused_options` gives why their values cannot be honoured ("": they
  // can; empty function: no such values).
  std::vector<std::string> own_options;
  // Own options the result file records only when their value (as the option names it) is not
  // the one given here: the value every run of the method had before the option existed, so
  // that those runs keep their result files ({field, value}).
  std::vector<std::pair<std::string, std::string>> recorded_unless;
  std::function<std::vector<std::string>(const ProgressiveOptions& options)> changed_options;
  std::function<std::string(const ProgressiveOptions& options)> refused_options;
  // The run summary: how the method is set ("16 samples per shooter"), and the line of what
  // it counted, {label, text}.
  std::function<std::string(const ProgressiveOptions& options)> setting;
  std::function<std::pair<std::string, std::string>(const WorkCounts& counts)> counted;
  // The prefix of the WorkCounts counters only this method counts ("": none): the result
  // file writes them for runs of this method only, so that other runs keep their files.
  std::string counter_prefix;
};

// The paper's ray-traced form factors first (the default), then the hemicube, then any
// added with add_form_factor_method.
const MethodRegistry<FormFactorMethod>& form_factor_methods();

// Registers one more method from outside the list, before the registry is first read
// (std::logic_error after): for tests/throwaway_methods.cpp, which checks that every consumer
// knows a method from its registration alone.
void add_form_factor_method(FormFactorMethod method);

// Whether the result file of a run with form-factor method `method` writes `counter`.
bool writes_counter(const std::string& method, const std::string& counter);

}  // namespace ncube

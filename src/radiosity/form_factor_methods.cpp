#include "radiosity/form_factor_methods.h"

#include "radiosity/form_factor.h"
#include "radiosity/hemicube.h"

namespace ncube {

namespace {

// Section 2.2: a ray from each receiver to every part of the shooter, tested against the
// node's patches; the form factor of the visible parts by the contour integral.
void shoot_ray_traced(RadiosityEngine& engine, const OccluderSet& occluders, const Shooter& shooter,
                      const std::vector<ElementRef>& receivers, const ProgressiveOptions&,
                      WorkCounts& counts) {
  const std::vector<PartMask> masks = visible_parts(engine, occluders, receivers, shooter, counts);
  engine.gather(shooter, receivers, masks, counts);
}

// The shooter's hemicube over the node's geometry: its receivers as items, every other
// polygon it holds (its other elements, the patches it holds for visibility only) as
// occluders; the shooter's own patch lies in the eye's plane and is left out. Without
// subdivision every processor draws the same polygons (each patch's elements), so the
// answers do not depend on R.
std::vector<double> hemicube_shot_form_factors(RadiosityEngine& engine, const OccluderSet& occluders,
                                               const Shooter& shooter,
                                               const std::vector<ElementRef>& receivers,
                                               const ProgressiveOptions& options, WorkCounts& counts) {
  const Scene& scene = engine.scene();
  const ElementStore& store = engine.store();
  std::vector<HemicubePolygon> items;
  items.reserve(receivers.size());
  std::vector<std::vector<bool>> receiving(store.patches().size());
  for (std::size_t slot = 0; slot < store.patches().size(); ++slot)
    receiving[slot].assign(store.patches()[slot].elements.size(), false);
  for (const ElementRef& ref : receivers) {
    const StoredElement& element = store.element(ref);
    const int patch = store.patches()[std::size_t(ref.slot)].patch;
    items.push_back(hemicube_polygon(scene, patch, cell_polygon(scene.patches[std::size_t(patch)], element.cell),
                                     element.area));
    receiving[std::size_t(ref.slot)][std::size_t(ref.index)] = true;
  }
  std::vector<HemicubePolygon> blockers;
  for (std::size_t slot = 0; slot < store.patches().size(); ++slot) {
    const StoredPatch& s = store.patches()[slot];
    if (s.patch == shooter.patch) continue;
    const Patch& patch = scene.patches[std::size_t(s.patch)];
    for (std::size_t k = 0; k < s.elements.size(); ++k)
      if (!receiving[slot][k])
        blockers.push_back(hemicube_polygon(scene, s.patch, cell_polygon(patch, s.elements[k].cell),
                                            s.elements[k].area));
  }
  // The patches it holds for visibility only, cut into the scene's element grid (nu x nv,
  // known to every node): drawn whole, a patch's outline would cover a cell centre lying on
  // it where its owner's elements, whose edges are the outline's to rounding, do not, and the
  // answers would depend on how the patches are spread (R = 1 against R = 8, scene1: 0.3 %).
  for (int patch : occluders.patch_indices())
    if (patch != shooter.patch && !store.holds(patch)) {
      const Patch& p = scene.patches[std::size_t(patch)];
      for (int e = p.first_element; e < p.first_element + p.element_count(); ++e)
        blockers.push_back(hemicube_polygon(scene, patch, scene.elements[std::size_t(e)].polygon,
                                            scene.elements[std::size_t(e)].area));
    }
  return hemicube_form_factors(scene, shooter.patch, items, blockers, options.hemicube, counts);
}

void shoot_hemicube(RadiosityEngine& engine, const OccluderSet& occluders, const Shooter& shooter,
                    const std::vector<ElementRef>& receivers, const ProgressiveOptions& options,
                    WorkCounts& counts) {
  const std::vector<double> form_factors =
      hemicube_shot_form_factors(engine, occluders, shooter, receivers, options, counts);
  engine.gather_form_factors(shooter, receivers, form_factors, counts);
}

std::vector<double> ray_traced_shot_form_factors(RadiosityEngine& engine, const OccluderSet& occluders,
                                                 const Shooter& shooter,
                                                 const std::vector<ElementRef>& receivers,
                                                 const ProgressiveOptions&, WorkCounts& counts) {
  return ray_traced_form_factors(engine, occluders, receivers, shooter, counts);
}

// Section 3: with visibility processors, the light of a block through the parts the AND of
// their answers marks visible (the form factors computed ahead on the host when it can).
void gather_ray_traced_block(RadiosityEngine& engine, const Shooter& shooter,
                             const std::vector<ElementRef>& receivers, const PointBlocks& blocks,
                             int block, const std::vector<PartMask>& masks, WorkCounts& counts) {
  engine.gather_block(shooter, receivers, blocks, block, masks, counts);
}

FormFactorMethod ray_traced() {
  FormFactorMethod m;
  m.name = "ray-traced";
  m.doc = "section 2.2: rays from each element to the shooter's M parts, the visible parts' "
          "point-to-polygon form factors; the calibrated setup";
  m.shoot = shoot_ray_traced;
  m.form_factors = ray_traced_shot_form_factors;
  m.gather_visible = gather_ray_traced_block;
  m.setup_work = [](const ProgressiveOptions&) { return WorkCounts{}; };
  m.node_items = [](const ProgressiveOptions&) { return HeldItems{}; };
  m.setting = [](const ProgressiveOptions& options) {
    return std::to_string(options.samples) + " samples per shooter";
  };
  m.counted = [](const WorkCounts& counts) {
    return std::make_pair(std::string("ray-patch tests"),
                          std::to_string(counts.ray_patch_tests) + " (" +
                              std::to_string(counts.plane_crossings) +
                              " of them cross the patch's plane)");
  };
  return m;
}

FormFactorMethod hemicube() {
  FormFactorMethod m;
  m.name = "hemicube";
  m.doc = "Cohen & Greenberg's hemicube at the shooter (--hemicube-resolution, "
          "--hemicube-placement, --hemicube-back-faces, --hemicube-reciprocity); V = 0 only";
  m.shoot = shoot_hemicube;
  m.form_factors = hemicube_shot_form_factors;
  m.without_visibility_processors =
      "each radiosity processor renders the shooter's hemicube over the geometry it holds, "
      "which with visibility processors is only its own patches (docs/model.md, \"The "
      "hemicube\")";
  m.setup_work = [](const ProgressiveOptions& options) {
    return hemicube_setup_work(options.hemicube);
  };
  m.node_items = [](const ProgressiveOptions& options) {
    HeldItems items;
    items.delta_form_factors = hemicube_table_entries(options.hemicube);
    items.hemicube_cells = hemicube_buffer_cells(options.hemicube);
    return items;
  };
  m.traces_rays = false;
  m.own_options = {"hemicube_resolution", "hemicube_placement", "hemicube_back_faces",
                   "hemicube_reciprocity"};
  // Every hemicube run blocked at back faces, and kept its reciprocal factors as computed,
  // before --hemicube-back-faces and --hemicube-reciprocity existed.
  m.recorded_unless = {{"hemicube_back_faces", "block"}, {"hemicube_reciprocity", "as-computed"}};
  m.changed_options = [](const ProgressiveOptions& options) {
    const HemicubeOptions& o = options.hemicube;
    const HemicubeOptions defaults;
    std::vector<std::string> changed;
    if (o.resolution != defaults.resolution)
      changed.push_back("--hemicube-resolution " + std::to_string(o.resolution));
    if (o.placement != defaults.placement)
      changed.push_back(std::string("--hemicube-placement ") + hemicube_placement_name(o.placement));
    if (o.back_faces != defaults.back_faces)
      changed.push_back(std::string("--hemicube-back-faces ") +
                        hemicube_back_faces_name(o.back_faces));
    // The guard, a variant of the method (docs/model.md, "The hemicube": "Reciprocity").
    if (o.reciprocity != defaults.reciprocity)
      changed.push_back(std::string("--hemicube-reciprocity ") +
                        hemicube_reciprocity_name(o.reciprocity));
    return changed;
  };
  m.refused_options = [](const ProgressiveOptions& options) {
    if (is_valid_hemicube_resolution(options.hemicube.resolution)) return std::string();
    return "--hemicube-resolution " + std::to_string(options.hemicube.resolution) +
           ": must be an even number from " + std::to_string(kMinHemicubeResolution) + " to " +
           std::to_string(kMaxHemicubeResolution);
  };
  m.setting = [](const ProgressiveOptions& options) {
    return "hemicube N=" + std::to_string(options.hemicube.resolution) + " at the shooter's " +
           hemicube_placement_name(options.hemicube.placement);
  };
  m.counted = [](const WorkCounts& counts) {
    return std::make_pair(std::string("hemicube cells"),
                          std::to_string(counts.hemicube_depth_tests) + " depth-tested, " +
                              std::to_string(counts.hemicube_cells_read) + " read out, " +
                              std::to_string(counts.hemicube_reciprocal_above_one) +
                              " receivers' form factors above 1 by reciprocity");
  };
  m.counter_prefix = "hemicube_";
  return m;
}

// Methods added from outside the list (add_form_factor_method), and whether the registry has
// been read, after which none may be added.
std::vector<FormFactorMethod>& added_methods() {
  static std::vector<FormFactorMethod> added;
  return added;
}

bool& registry_read() {
  static bool read = false;
  return read;
}

}  // namespace

const MethodRegistry<FormFactorMethod>& form_factor_methods() {
  static const MethodRegistry<FormFactorMethod> registry = [] {
    std::vector<FormFactorMethod> methods{ray_traced(), hemicube()};
    for (FormFactorMethod& method : added_methods()) methods.push_back(std::move(method));
    registry_read() = true;
    return MethodRegistry<FormFactorMethod>("form-factor method", std::move(methods));
  }();
  return registry;
}

void add_form_factor_method(FormFactorMethod method) {
  if (registry_read())
    throw std::logic_error("form-factor method \"" + method.name +
                           "\" added after the registry was read");
  added_methods().push_back(std::move(method));
}

bool writes_counter(const std::string& method, const std::string& counter) {
  for (const FormFactorMethod& m : form_factor_methods().all())
    if (!m.counter_prefix.empty() && counter.rfind(m.counter_prefix, 0) == 0) return m.name == method;
  return true;
}

}  // namespace ncube

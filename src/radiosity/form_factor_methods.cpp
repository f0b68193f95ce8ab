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

}  // namespace

const MethodRegistry<FormFactorMethod>& form_factor_methods() {
  static const MethodRegistry<FormFactorMethod> registry(
      "form-factor method",
      {
          {"ray-traced",
           "section 2.2: rays from each element to the shooter's M parts, the visible parts' "
           "point-to-polygon form factors; the calibrated setup",
           shoot_ray_traced, ray_traced_shot_form_factors, [](const ProgressiveOptions&) { return WorkCounts{}; },
           [](const ProgressiveOptions&) { return HeldItems{}; }, true, "", ""},
          {"hemicube",
           "Cohen & Greenberg's hemicube at the shooter (--hemicube-resolution, "
           "--hemicube-placement, --hemicube-back-faces); V = 0 only",
           shoot_hemicube, hemicube_shot_form_factors,
           [](const ProgressiveOptions& options) { return hemicube_setup_work(options.hemicube); },
           [](const ProgressiveOptions& options) {
             HeldItems items;
             items.delta_form_factors = hemicube_table_entries(options.hemicube);
             items.hemicube_cells = hemicube_buffer_cells(options.hemicube);
             return items;
           },
           false,
           "each radiosity processor renders the shooter's hemicube over the geometry it "
           "holds, which with visibility processors is only its own patches (docs/model.md, "
           "\"The hemicube\")",
           "hemicube_"},
      });
  return registry;
}

bool writes_counter(const std::string& method, const std::string& counter) {
  for (const FormFactorMethod& m : form_factor_methods().all())
    if (!m.counter_prefix.empty() && counter.rfind(m.counter_prefix, 0) == 0) return m.name == method;
  return true;
}

}  // namespace ncube

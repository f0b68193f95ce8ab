#include "radiosity/radiosity_engine.h"

#include <algorithm>
#include <bitset>
#include <stdexcept>
#include <glm/geometric.hpp>

#include "radiosity/form_factor.h"
#include "radiosity/form_factor_methods.h"

namespace ncube {

RadiosityEngine::RadiosityEngine(const Scene& scene, const std::vector<int>& owned_patches)
    : store_(scene, owned_patches) {}

void RadiosityEngine::use_host_assist(HostAssist* assist, int rank) {
  assist_ = assist;
  if (assist_) assist_->engine_started(rank, *this);
}

ShooterChoice RadiosityEngine::best_shooter(WorkCounts& counts) const {
  ShooterChoice best;
  for (const StoredPatch& s : store_.patches()) {
    const Rgb& u = s.unshot;
    ShooterChoice candidate{s.patch, (u.r + u.g + u.b) * scene().patches[std::size_t(s.patch)].area, u};
    if (candidate.better_than(best)) best = candidate;
  }
  counts.shooter_candidates += store_.patches().size();
  return best;
}

std::vector<ElementRef> RadiosityEngine::receivers(const Shooter& shooter, bool skip_facing_away,
                                                   WorkCounts& counts) const {
  std::vector<ElementRef> result;
  const auto& patches = store_.patches();
  for (int slot = 0; slot < int(patches.size()); ++slot) {
    const StoredPatch& s = patches[std::size_t(slot)];
    counts.receivers += s.elements.size();
    if (s.patch == shooter.patch) continue;  // a patch does not light itself
    const Vec3& normal = scene().patches[std::size_t(s.patch)].normal;
    for (int k = 0; k < int(s.elements.size()); ++k)
      if (!skip_facing_away || faces_shooter(s.elements[std::size_t(k)].centre, normal, shooter))
        result.push_back({slot, k});
  }
  return result;
}

void RadiosityEngine::visibility_points(const std::vector<ElementRef>& receivers,
                                        std::vector<Vec3>& points, std::vector<int>& patches) const {
  points.resize(receivers.size());
  patches.resize(receivers.size());
  for (std::size_t k = 0; k < receivers.size(); ++k) {
    points[k] = store_.element(receivers[k]).centre;
    patches[k] = store_.patches()[std::size_t(receivers[k].slot)].patch;
  }
}

double receiver_form_factor(const Shooter& shooter, const Vec3& centre, const Vec3& normal,
                            PartMask mask) {
  // The shooter emits from its front only: a receiver behind its plane gets nothing.
  if (!shooter_lights(shooter, centre)) return 0.0;
  return visible_parts_form_factor(centre, normal, shooter, mask);
}

PointBlocks RadiosityEngine::point_blocks(const Shooter& shooter,
                                          const std::vector<ElementRef>& receivers,
                                          int block_size) const {
  PointBlocks blocks;
  visibility_points(receivers, blocks.points, blocks.patches);
  blocks.block_size = std::max(1, block_size);
  if (assist_) blocks.posted = assist_->blocks_to_send(shooter, blocks.points, blocks.patches, block_size);
  return blocks;
}

void RadiosityEngine::gather(const Shooter& shooter, const std::vector<ElementRef>& receivers,
                             const std::vector<PartMask>& masks, WorkCounts& counts) {
  add_light(shooter, receivers, masks, nullptr, counts);
}

void RadiosityEngine::gather_block(const Shooter& shooter, const std::vector<ElementRef>& receivers,
                                   const PointBlocks& blocks, int block,
                                   const std::vector<PartMask>& masks, WorkCounts& counts) {
  const std::vector<ElementRef> part(receivers.begin() + std::ptrdiff_t(blocks.first(block)),
                                     receivers.begin() + std::ptrdiff_t(blocks.end(block)));
  const double* form_factors =
      assist_ && blocks.posted ? assist_->form_factors(*blocks.posted, block, masks.data(), masks.size())
                               : nullptr;
  add_light(shooter, part, masks, form_factors, counts);
}

std::vector<double> RadiosityEngine::form_factors(const Shooter& shooter,
                                                  const std::vector<ElementRef>& receivers,
                                                  const std::vector<PartMask>& masks) {
  std::vector<double> form_factors;
  std::vector<Vec3> points;
  std::vector<int> patches;
  const bool remembering = assist_ && assist_->remembers_form_factors();
  if (remembering) {  // the same question asked in an earlier shot?
    visibility_points(receivers, points, patches);
    form_factors.assign(receivers.size(), 0.0);
    if (assist_->remembered_form_factors(shooter, PointBlock(points, patches), masks.data(),
                                         form_factors.data()))
      return form_factors;
  }
  form_factors.assign(receivers.size(), 0.0);
  const auto compute = [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) {
      const StoredElement& element = store_.element(receivers[k]);
      const int patch = store_.patches()[std::size_t(receivers[k].slot)].patch;
      form_factors[k] = receiver_form_factor(shooter, element.centre,
                                             scene().patches[std::size_t(patch)].normal, masks[k]);
    }
  };
  // Each receiver's form factor is independent of the others': the host may compute them
  // on several threads (host_assist.h).
  if (assist_) {
    assist_->share_out(receivers.size(), 64, compute);
    if (remembering)
      assist_->remember_form_factors(shooter, PointBlock(points, patches), masks.data(),
                                     form_factors.data());
  } else {
    compute(0, receivers.size());
  }
  return form_factors;
}

void RadiosityEngine::add_light(const Shooter& shooter, const std::vector<ElementRef>& receivers,
                                const std::vector<PartMask>& masks,
                                const double* computed_form_factors, WorkCounts& counts) {
  std::vector<double> form_factors;
  if (!computed_form_factors) {
    form_factors = this->form_factors(shooter, receivers, masks);
    computed_form_factors = form_factors.data();
  }
  for (std::size_t k = 0; k < receivers.size(); ++k) {
    const PartMask mask = shooter_lights(shooter, store_.element(receivers[k]).centre) ? masks[k] : 0;
    counts.form_factors += std::bitset<64>(mask).count();
    if (mask != 0) {
      const StoredElement& element = store_.element(receivers[k]);
      const int patch = store_.patches()[std::size_t(receivers[k].slot)].patch;
      counts.form_factor_edge_terms += form_factor_edge_terms(
          element.centre, scene().patches[std::size_t(patch)].normal, shooter, mask);
    }
    receive(shooter, receivers[k], computed_form_factors[k], counts);
  }
}

void RadiosityEngine::gather_form_factors(const Shooter& shooter,
                                          const std::vector<ElementRef>& receivers,
                                          const std::vector<double>& form_factors,
                                          WorkCounts& counts) {
  for (std::size_t k = 0; k < receivers.size(); ++k)
    receive(shooter, receivers[k], form_factors[k], counts);
}

void RadiosityEngine::receive(const Shooter& shooter, const ElementRef& ref, double form_factor,
                              WorkCounts& counts) {
  StoredPatch& s = store_.patches()[std::size_t(ref.slot)];
  StoredElement& element = s.elements[std::size_t(ref.index)];
  const Patch& patch = scene().patches[std::size_t(s.patch)];
  // Reciprocity: B_e gains rho_e * F(e -> shooter) * unshot (section 1.1, shooting form).
  const Rgb gained = patch.reflectance * shooter.unshot * form_factor;
  element.radiosity += gained;
  element.shot_gain = gained;
  s.unshot += gained * (element.area / patch.area);
  ++counts.element_updates;
}

std::vector<ElementRef> RadiosityEngine::subdivide(const std::vector<ElementRef>& shot,
                                                   const SubdivisionOptions& options, long room,
                                                   bool& out_of_room, WorkCounts& counts) {
  std::vector<ElementRef> children;
  std::size_t next = 0;
  while (next < shot.size()) {  // one patch (slot) at a time; `shot` is in store order
    const int slot = shot[next].slot;
    StoredPatch& s = store_.patches()[std::size_t(slot)];
    const Patch& patch = scene().patches[std::size_t(s.patch)];
    std::vector<Rgb> radiosity;
    radiosity.reserve(s.elements.size());
    for (const StoredElement& e : s.elements) radiosity.push_back(e.radiosity);
    const PatchMesh& mesh = store_.mesh(slot);
    std::vector<int> cuts;  // ascending
    for (; next < shot.size() && shot[next].slot == slot; ++next) {
      const int k = shot[next].index;
      const StoredElement& e = s.elements[std::size_t(k)];
      ++counts.subdivision_tests;
      if (!should_cut(options, mesh, radiosity, std::size_t(k), e.cell, e.area)) continue;
      if (room < 4) {
        out_of_room = true;
        continue;
      }
      room -= 4;
      cuts.push_back(k);
    }
    // Take back each cut element's share of this shot, then cut from the back so that the
    // indices still to cut stay valid.
    for (int k : cuts) {
      const StoredElement& e = s.elements[std::size_t(k)];
      s.unshot -= e.shot_gain * (e.area / patch.area);
    }
    for (auto it = cuts.rbegin(); it != cuts.rend(); ++it) {
      const StoredElement& e = s.elements[std::size_t(*it)];
      store_.cut(slot, *it, e.radiosity - e.shot_gain);
      counts.elements_created += 4;
    }
    for (std::size_t t = 0; t < cuts.size(); ++t)
      for (int m = 0; m < 4; ++m) children.push_back({slot, cuts[t] + 3 * int(t) + m});
  }
  return children;
}

void RadiosityEngine::finish_shot(int patch) {
  const int slot = store_.slot_of(patch);
  if (slot >= 0) store_.patches()[std::size_t(slot)].unshot = Rgb(0.0);
  if (assist_) assist_->shot_finished(*this);
}

const Rgb& RadiosityEngine::unshot(int patch) const {
  const int slot = store_.slot_of(patch);
  if (slot < 0) throw std::logic_error("RadiosityEngine::unshot: patch not held");
  return store_.patches()[std::size_t(slot)].unshot;
}

Rgb RadiosityEngine::patch_radiosity(int patch) const {
  const int slot = store_.slot_of(patch);
  if (slot < 0) throw std::logic_error("RadiosityEngine::patch_radiosity: patch not held");
  const StoredPatch& s = store_.patches()[std::size_t(slot)];
  Rgb sum(0.0);
  for (const StoredElement& e : s.elements) sum += e.radiosity * e.area;
  return sum / scene().patches[std::size_t(patch)].area;
}

const Rgb& RadiosityEngine::element_radiosity(int e) const {
  const int patch = scene().elements[std::size_t(e)].patch;
  const int slot = store_.slot_of(patch);
  const StoredPatch& s = store_.patches()[std::size_t(slot)];
  const std::size_t index = std::size_t(e - scene().patches[std::size_t(patch)].first_element);
  if (slot < 0 || s.elements.size() != std::size_t(scene().patches[std::size_t(patch)].element_count()))
    throw std::logic_error("RadiosityEngine::element_radiosity: patch not held, or cut");
  return s.elements[index].radiosity;
}

bool has_converged(const ShooterChoice& best, double emitted_power, double fraction) {
  return best.patch < 0 || best.power < fraction * emitted_power;
}

std::vector<PartMask> visible_parts(const RadiosityEngine& engine, const OccluderSet& occluders,
                                    const std::vector<ElementRef>& receivers,
                                    const Shooter& shooter, WorkCounts& counts) {
  std::vector<Vec3> points;
  std::vector<int> patches;
  engine.visibility_points(receivers, points, patches);
  std::vector<PartMask> masks(receivers.size());
  occluders.unblocked_parts(PointBlock(points, patches), shooter, masks.data(), counts);
  count_blocked_rays(masks.data(), masks.size(), shooter, counts);
  return masks;
}

ProgressiveRun run_progressive(RadiosityEngine& engine, const OccluderSet& occluders,
                               const ProgressiveOptions& options) {
  ProgressiveRun run;
  const double emitted = engine.scene().emitted_power();
  for (;;) {
    WorkCounts counts;
    const ShooterChoice best = engine.best_shooter(counts);
    if (has_converged(best, emitted, options.convergence_fraction)) {
      run.converged = true;
      break;
    }
    if (options.max_iterations >= 0 && run.iterations >= options.max_iterations) break;
    const Shooter shooter = make_shooter(engine.scene(), best.patch, best.unshot, options.samples);
    std::vector<ElementRef> receivers = engine.receivers(shooter, options.skip_facing_away, counts);
    // Section 4.1: shoot, then cut where the light changes too fast and shoot the current
    // shooter to the new elements, until no element is cut.
    while (!receivers.empty()) {
      form_factor_methods().at(options.form_factors).shoot(engine, occluders, shooter, receivers,
                                                           options, counts);
      if (!options.subdivision.enabled) break;
      bool out_of_room = false;
      receivers = engine.subdivide(receivers, options.subdivision, 1L << 62, out_of_room, counts);
    }
    engine.finish_shot(best.patch);
    ++run.iterations;
    run.shooters.push_back(best.patch);
    run.elements.push_back(engine.store().element_count());
    run.per_iteration.push_back(counts);
    run.total += counts;
  }
  return run;
}

}  // namespace ncube

#include "radiosity/radiosity_engine.h"

#include <bitset>
#include <glm/geometric.hpp>

#include "radiosity/form_factor.h"
#include "radiosity/host_threads.h"

namespace ncube {

RadiosityEngine::RadiosityEngine(const Scene& scene, std::vector<int> owned_patches)
    : scene_(scene),
      owned_(std::move(owned_patches)),
      radiosity_(scene.elements.size(), Rgb(0.0)),
      unshot_(scene.patches.size(), Rgb(0.0)) {
  for (int p : owned_) {
    const Patch& patch = scene.patches[p];
    unshot_[p] = patch.emission;
    for (int e = patch.first_element; e < patch.first_element + patch.element_count(); ++e) {
      owned_elements_.push_back(e);
      radiosity_[e] = patch.emission;
    }
  }
}

ShooterChoice RadiosityEngine::best_shooter(WorkCounts& counts) const {
  ShooterChoice best;
  for (int p : owned_) {
    const Rgb& u = unshot_[p];
    ShooterChoice candidate{p, (u.r + u.g + u.b) * scene_.patches[p].area, u};
    if (candidate.better_than(best)) best = candidate;
  }
  counts.shooter_candidates += owned_.size();
  return best;
}

std::vector<int> RadiosityEngine::receivers(const Shooter& shooter, bool skip_facing_away,
                                            WorkCounts& counts) const {
  std::vector<int> result;
  for (int e : owned_elements_) {
    const Element& element = scene_.elements[e];
    if (element.patch == shooter.patch) continue;  // a patch does not light itself
    if (!skip_facing_away ||
        faces_shooter(element.centre, scene_.patches[element.patch].normal, shooter))
      result.push_back(e);
  }
  counts.receivers += owned_elements_.size();
  return result;
}

void RadiosityEngine::gather(const Shooter& shooter, const std::vector<int>& receivers,
                             const std::vector<PartMask>& masks, WorkCounts& counts, int threads) {
  std::vector<double> form_factors(receivers.size(), 0.0);
  parallel_chunks(threads, receivers.size(), 64, [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) {
      const Element& element = scene_.elements[receivers[k]];
      // The shooter emits from its front only: a receiver behind its plane gets nothing.
      if (!(glm::dot(shooter.normal, element.centre - shooter.polygon[0]) > 0.0)) continue;
      form_factors[k] = visible_parts_form_factor(
          element.centre, scene_.patches[element.patch].normal, shooter, masks[k]);
    }
  });
  for (std::size_t k = 0; k < receivers.size(); ++k) {
    const Element& element = scene_.elements[receivers[k]];
    const Patch& patch = scene_.patches[element.patch];
    const PartMask mask =
        glm::dot(shooter.normal, element.centre - shooter.polygon[0]) > 0.0 ? masks[k] : 0;
    counts.form_factors += std::bitset<64>(mask).count();
    // Reciprocity: B_e gains rho_e * F(e -> shooter) * unshot (section 1.1, shooting form).
    const Rgb gained = patch.reflectance * shooter.unshot * form_factors[k];
    radiosity_[receivers[k]] += gained;
    unshot_[element.patch] += gained * (element.area / patch.area);
    ++counts.element_updates;
  }
}

Rgb RadiosityEngine::patch_radiosity(int patch) const {
  const Patch& p = scene_.patches[patch];
  Rgb sum(0.0);
  for (int e = p.first_element; e < p.first_element + p.element_count(); ++e)
    sum += radiosity_[e] * scene_.elements[e].area;
  return sum / p.area;
}

bool has_converged(const ShooterChoice& best, double emitted_power, double fraction) {
  return best.patch < 0 || best.power < fraction * emitted_power;
}

std::vector<PartMask> visible_parts(const Scene& scene, const Occluders& occluders,
                                    const std::vector<int>& receivers, const Shooter& shooter,
                                    WorkCounts& counts, int threads) {
  std::vector<Vec3> points(receivers.size());
  std::vector<int> patches(receivers.size());
  for (std::size_t k = 0; k < receivers.size(); ++k) {
    points[k] = scene.elements[receivers[k]].centre;
    patches[k] = scene.elements[receivers[k]].patch;
  }
  std::vector<PartMask> masks(receivers.size());
  occluders.unblocked_parts(points.data(), patches.data(), receivers.size(), shooter, masks.data(),
                            counts, threads);
  return masks;
}

ProgressiveRun run_progressive(RadiosityEngine& engine, const Occluders& occluders,
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
    const std::vector<int> receivers = engine.receivers(shooter, options.skip_facing_away, counts);
    const std::vector<PartMask> masks =
        visible_parts(engine.scene(), occluders, receivers, shooter, counts, options.host_threads);
    engine.gather(shooter, receivers, masks, counts, options.host_threads);
    engine.clear_unshot(best.patch);
    ++run.iterations;
    run.shooters.push_back(best.patch);
    run.per_iteration.push_back(counts);
    run.total += counts;
  }
  return run;
}

}  // namespace ncube

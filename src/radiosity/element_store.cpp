#include "radiosity/element_store.h"

#include <algorithm>
#include <stdexcept>

namespace ncube {

StoredElement make_element(const Patch& patch, const ElementCell& cell, const Rgb& radiosity) {
  const Polygon polygon = cell_polygon(patch, cell);
  StoredElement e;
  e.cell = cell;
  e.centre = polygon.centroid();
  e.area = polygon.area();
  e.radiosity = radiosity;
  return e;
}

StoredPatch initial_patch(const Scene& scene, int patch) {
  const Patch& p = scene.patches[std::size_t(patch)];
  StoredPatch stored;
  stored.patch = patch;
  stored.unshot = p.emission;
  stored.elements.reserve(std::size_t(p.element_count()));
  for (int j = 0; j < p.nv; ++j)
    for (int i = 0; i < p.nu; ++i) stored.elements.push_back(make_element(p, {0, i, j}, p.emission));
  return stored;
}

ElementStore::ElementStore(const Scene& scene, const std::vector<int>& patches) : scene_(&scene) {
  std::vector<int> sorted = patches;
  std::sort(sorted.begin(), sorted.end());
  patches_.reserve(sorted.size());
  for (int p : sorted) patches_.push_back(initial_patch(scene, p));
}

int ElementStore::slot_of(int patch) const {
  const auto it = std::lower_bound(patches_.begin(), patches_.end(), patch,
                                   [](const StoredPatch& s, int p) { return s.patch < p; });
  return it != patches_.end() && it->patch == patch ? int(it - patches_.begin()) : -1;
}

std::vector<int> ElementStore::patch_indices() const {
  std::vector<int> result;
  result.reserve(patches_.size());
  for (const StoredPatch& s : patches_) result.push_back(s.patch);
  return result;
}

long ElementStore::element_count() const {
  long total = 0;
  for (const StoredPatch& s : patches_) total += long(s.elements.size());
  return total;
}

const PatchMesh& ElementStore::mesh(int slot) const {
  const StoredPatch& s = patches_[std::size_t(slot)];
  if (!s.mesh) {
    std::vector<ElementCell> cells;
    cells.reserve(s.elements.size());
    for (const StoredElement& e : s.elements) cells.push_back(e.cell);
    // The cache is not part of the store's value: building it changes nothing observable.
    const_cast<StoredPatch&>(s).mesh =
        std::make_shared<const PatchMesh>(scene_->patches[std::size_t(s.patch)], cells);
  }
  return *s.mesh;
}

void ElementStore::cut(int slot, int index, const Rgb& child_radiosity) {
  StoredPatch& s = patches_[std::size_t(slot)];
  const Patch& patch = scene_->patches[std::size_t(s.patch)];
  const ElementCell parent = s.elements[std::size_t(index)].cell;
  const auto children = parent.children();
  std::vector<StoredElement> made;
  for (const ElementCell& c : children) made.push_back(make_element(patch, c, child_radiosity));
  s.elements[std::size_t(index)] = made[0];
  s.elements.insert(s.elements.begin() + index + 1, made.begin() + 1, made.end());
  s.mesh.reset();
}

StoredPatch ElementStore::remove(int patch) {
  const int slot = slot_of(patch);
  if (slot < 0) throw std::logic_error("ElementStore::remove: patch not held");
  StoredPatch taken = std::move(patches_[std::size_t(slot)]);
  patches_.erase(patches_.begin() + slot);
  return taken;
}

void ElementStore::insert(StoredPatch patch) {
  if (holds(patch.patch)) throw std::logic_error("ElementStore::insert: patch already held");
  const auto it = std::lower_bound(patches_.begin(), patches_.end(), patch.patch,
                                   [](const StoredPatch& s, int p) { return s.patch < p; });
  patches_.insert(it, std::move(patch));
}

std::vector<PatchSolution> ElementStore::solution() const {
  std::vector<PatchSolution> result;
  result.reserve(patches_.size());
  for (const StoredPatch& s : patches_) {
    PatchSolution p;
    p.patch = s.patch;
    for (const StoredElement& e : s.elements) {
      p.cells.push_back(e.cell);
      p.radiosity.push_back(e.radiosity);
    }
    result.push_back(std::move(p));
  }
  return result;
}

}  // namespace ncube

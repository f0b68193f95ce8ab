// The elements one radiosity processor holds (paper section 4: "we subdivide each patch into
// elements and store these elements locally on the processor"): its patches, each with its
// unshot radiosity and its elements, cells of the patch's grid at any level (4.1), in a
// fixed order. Patches can leave and join the store (4.2, load balancing); their elements
// travel with them.
#pragma once

#include <memory>
#include <vector>

#include "scene/patch_mesh.h"

namespace ncube {

struct StoredElement {
  ElementCell cell;
  Vec3 centre{0.0};  // the visibility point (section 4)
  double area = 0.0;
  Rgb radiosity{0.0};
  Rgb shot_gain{0.0};  // the light of the current shot (taken back when the element is cut)
};

struct StoredPatch {
  int patch = -1;
  Rgb unshot{0.0};
  std::vector<StoredElement> elements;
  // The mesh of the elements' cells, kept until they change (built on demand).
  std::shared_ptr<const PatchMesh> mesh;
};

// An element of a store: its patch's slot and its index among the patch's elements. Valid
// until the store changes (a cut or a transfer).
struct ElementRef {
  int slot = 0;
  int index = 0;
};

// A patch's elements at level 0, as Scene::build_elements orders them (row by row).
StoredPatch initial_patch(const Scene& scene, int patch);
StoredElement make_element(const Patch& patch, const ElementCell& cell, const Rgb& radiosity);

class ElementStore {
 public:
  // The given patches (any order; kept in scene order), each at level 0 with its emission
  // as radiosity and unshot radiosity.
  ElementStore(const Scene& scene, const std::vector<int>& patches);

  const Scene& scene() const { return *scene_; }
  const std::vector<StoredPatch>& patches() const { return patches_; }
  std::vector<StoredPatch>& patches() { return patches_; }
  const StoredElement& element(const ElementRef& ref) const {
    return patches_[std::size_t(ref.slot)].elements[std::size_t(ref.index)];
  }
  StoredElement& element(const ElementRef& ref) {
    return patches_[std::size_t(ref.slot)].elements[std::size_t(ref.index)];
  }
  int slot_of(int patch) const;  // -1 when not held
  bool holds(int patch) const { return slot_of(patch) >= 0; }
  std::vector<int> patch_indices() const;
  long element_count() const;
  const PatchMesh& mesh(int slot) const;

  // Replaces element `index` of the patch in `slot` by its four children (in the order of
  // ElementCell::children), each with the given radiosity.
  void cut(int slot, int index, const Rgb& child_radiosity);

  // Load balancing (4.2): a patch leaves with its elements, or joins.
  StoredPatch remove(int patch);
  void insert(StoredPatch patch);

  // The solution of the held patches, in scene order.
  std::vector<PatchSolution> solution() const;

 private:
  const Scene* scene_;
  std::vector<StoredPatch> patches_;  // in scene order
};

}  // namespace ncube

#include "nodes/placement.h"

#include <algorithm>
#include <numeric>

namespace ncube {

std::vector<std::vector<int>> partition_patches_by_elements(const Scene& scene, int processors) {
  std::vector<int> by_size(scene.patches.size());
  std::iota(by_size.begin(), by_size.end(), 0);
  std::stable_sort(by_size.begin(), by_size.end(), [&](int a, int b) {
    return scene.patches[a].element_count() > scene.patches[b].element_count();
  });
  std::vector<std::vector<int>> owned(static_cast<std::size_t>(processors));
  std::vector<long> load(static_cast<std::size_t>(processors), 0);
  for (int patch : by_size) {
    const int target = int(std::min_element(load.begin(), load.end()) - load.begin());
    owned[target].push_back(patch);
    load[target] += scene.patches[patch].element_count();
  }
  for (auto& list : owned) std::sort(list.begin(), list.end());
  return owned;
}

std::vector<int> visibility_share(const Scene& scene, int shares, int j) {
  const long n = long(scene.patches.size());
  const long begin = n * j / shares, end = n * (j + 1) / shares;
  std::vector<int> share(std::size_t(end - begin));
  std::iota(share.begin(), share.end(), int(begin));
  return share;
}

}  // namespace ncube

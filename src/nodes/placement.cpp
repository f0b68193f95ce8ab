#include "nodes/placement.h"

#include <algorithm>
#include <functional>
#include <numeric>
#include <queue>
#include <utility>

namespace ncube {

std::vector<std::vector<int>> partition_patches_by_elements(const Scene& scene, int processors) {
  std::vector<int> by_size(scene.patches.size());
  std::iota(by_size.begin(), by_size.end(), 0);
  std::stable_sort(by_size.begin(), by_size.end(), [&](int a, int b) {
    return scene.patches[a].element_count() > scene.patches[b].element_count();
  });
  std::vector<std::vector<int>> owned(static_cast<std::size_t>(processors));
  // The processor with the fewest elements so far, the lower rank among equals: the top of
  // a heap of (elements, rank), so that 8,192 processors are not scanned for every patch.
  using Load = std::pair<long, int>;
  std::priority_queue<Load, std::vector<Load>, std::greater<Load>> fewest;
  for (int rank = 0; rank < processors; ++rank) fewest.emplace(0, rank);
  for (int patch : by_size) {
    const auto [elements, target] = fewest.top();
    fewest.pop();
    owned[std::size_t(target)].push_back(patch);
    fewest.emplace(elements + scene.patches[patch].element_count(), target);
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

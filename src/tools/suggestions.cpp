#include "tools/suggestions.h"

#include <algorithm>
#include <numeric>

namespace ncube {

std::size_t edit_distance(std::string_view a, std::string_view b) {
  // Three rows of the dynamic programme: i - 2, i - 1 and i (the swap looks two rows back).
  std::vector<std::size_t> before(b.size() + 1), previous(b.size() + 1), current(b.size() + 1);
  std::iota(previous.begin(), previous.end(), 0);
  for (std::size_t i = 1; i <= a.size(); ++i) {
    current[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t substitution = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      current[j] = std::min({previous[j] + 1, current[j - 1] + 1, substitution});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        current[j] = std::min(current[j], before[j - 2] + 1);
    }
    std::swap(before, previous);
    std::swap(previous, current);
  }
  return previous[b.size()];
}

namespace {

std::string_view without_dashes(std::string_view name) {
  const std::size_t first = std::min(name.find_first_not_of('-'), name.size());
  return name.substr(first);
}

std::string lower(std::string_view text) {
  std::string lowered(text);
  for (char& c : lowered)
    if (c >= 'A' && c <= 'Z') c = char(c - 'A' + 'a');
  return lowered;
}

// The known names with their distances, nearest first, ties in the order given. Dashes and
// letter case aside: -iterations and --Iterations are --iterations mistyped.
std::vector<std::pair<std::size_t, std::string>> ranked(std::string_view typed,
                                                        const std::vector<std::string>& known) {
  std::vector<std::pair<std::size_t, std::string>> ranks;
  const std::string typed_bare = lower(without_dashes(typed));
  for (const std::string& name : known)
    if (name != typed) ranks.emplace_back(edit_distance(typed_bare, lower(without_dashes(name))), name);
  std::stable_sort(ranks.begin(), ranks.end(),
                   [](const auto& x, const auto& y) { return x.first < y.first; });
  return ranks;
}

}  // namespace

std::vector<std::string> close_names(std::string_view typed, const std::vector<std::string>& known,
                                     std::size_t limit) {
  // Long inputs are no one's typo of a short name: no quadratic work on a huge argument.
  if (typed.size() > 1000) return {};
  const std::string bare = lower(without_dashes(typed));
  const std::size_t within = std::max<std::size_t>(2, bare.size() / 3);
  std::vector<std::string> close;
  std::size_t best = std::string::npos;  // the distance of the nearest offered
  for (const auto& [distance, name] : ranked(typed, known)) {
    const std::string name_bare = lower(without_dashes(name));
    const bool begins = bare.size() >= 3 && name_bare.compare(0, bare.size(), bare) == 0;
    // Near: within reach, and not a whole other name (x for R); only the nearest of them.
    const bool near = distance <= within && distance < std::max(bare.size(), name_bare.size()) &&
                      (best == std::string::npos || distance == best);
    if (near || begins) {
      if (near) best = distance;
      close.push_back(name);
    }
    if (close.size() == limit) break;
  }
  return close;
}

std::vector<std::string> nearest_names(std::string_view typed,
                                       const std::vector<std::string>& known, std::size_t limit) {
  std::vector<std::string> nearest;
  if (typed.size() > 1000) return nearest;
  for (const auto& ranked_name : ranked(typed, known)) {
    if (nearest.size() == limit) break;
    nearest.push_back(ranked_name.second);
  }
  return nearest;
}

std::string either_of(const std::vector<std::string>& names) {
  std::string text;
  for (std::size_t i = 0; i < names.size(); ++i)
    text += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
  return text;
}

std::string did_you_mean(std::string_view typed, const std::vector<std::string>& known) {
  const std::vector<std::string> close = close_names(typed, known);
  return close.empty() ? "" : "did you mean " + either_of(close) + "?";
}

}  // namespace ncube

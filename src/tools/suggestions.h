// "Did you mean": the names a mistyped one was nearest to (an option, a choice of a method or
// parallelisation, a scene, platform or machine name), by edit distance (docs/cli.md, "Names
// corrected").
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace ncube {

// The optimal-string-alignment distance: the fewest insertions, deletions, substitutions and
// swaps of two neighbouring characters (each counting 1) that turn `a` into `b`, byte by byte.
std::size_t edit_distance(std::string_view a, std::string_view b);

// The known names close to `typed` (dashes and letter case aside), at most `limit`, in the
// order of their distance: those at the smallest distance within max(2, length / 3) edits
// (length: of `typed` without leading dashes) that are not a whole other name, and those it
// begins (at least 3 characters besides dashes).
std::vector<std::string> close_names(std::string_view typed, const std::vector<std::string>& known,
                                     std::size_t limit = 3);

// The `limit` known names nearest to `typed`, however far (ties in the order given).
std::vector<std::string> nearest_names(std::string_view typed,
                                       const std::vector<std::string>& known, std::size_t limit = 3);

// "a", "a or b", "a, b or c".
std::string either_of(const std::vector<std::string>& names);

// "did you mean --iterations?" for the close names, or "" when none is close.
std::string did_you_mean(std::string_view typed, const std::vector<std::string>& known);

}  // namespace ncube

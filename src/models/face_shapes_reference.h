// The quadratic face tests as first written, kept as the readable definitions that the fast
// ones in face_shapes.cpp must match exactly (same doubles, same crossing pair, same triangles
// in the same order): tests/face_shapes_fast_test.cpp compares the two on many random
// polygons. Used only by tests and benchmarks; the importer calls face_shapes.h.
#pragma once

#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

#include "models/face_shapes.h"

namespace ncube::models::reference {

// The largest norm(a - b) over all pairs of corners: O(corners^2).
double diameter(const std::vector<Point>& corners);
// The first pair (i, j), i < j, in the order i then j, of edges that cross in the face's best
// plane: O(corners^2).
std::optional<std::pair<std::size_t, std::size_t>> crossing_edges(const std::vector<Point>& corners);
// Ear clipping that clips, at each step, the first corner in the face's order that is convex
// with no other remaining corner in its closed triangle: O(corners^3) at worst.
std::vector<std::vector<Point>> ear_clip(const std::vector<Point>& corners);

}  // namespace ncube::models::reference

// Which faces of a model are patches as they are and how the others are cut
// (docs/scene-format.md, "Importing models"): planar convex quads kept, bent quads cut along
// the diagonal from corner 0, other polygons ear-clipped, flat ones found. Tolerances are
// relative to the face's diameter, so a model's units do not matter.
#pragma once

#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace ncube::models {

using Point = glm::dvec3;

// Tolerances (docs/scene-format.md, "Importing models"), relative to the face's diameter d:
// a quad is kept when its fourth corner is within kPlanarity d of the plane of the first
// three and every corner turns the same way by more than kTurn d^2 (slightly stricter than
// the scene loader's 1e-6 and 1e-12, so a kept quad always loads); a face or triangle whose
// area is at most kFlat d^2 is degenerate; corners within kSame d of each other are one.
constexpr double kPlanarity = 1e-7;
constexpr double kTurn = 1e-9;
constexpr double kFlat = 1e-10;
constexpr double kSame = 1e-12;
// Faces of more corners are refused (docs/scene-format.md, "Importing models"): the tests and
// the cutting of a face use indexes (a face of this many corners on a circle imports in about
// 0.5 s, a comb in 1.7 s), but outlines of long edges or long thin ears still cost up to
// O(n^2) (docs/scene-format.md gives each test's complexity). 32,767 is also Assimp's own limit
// (AI_MAX_FACE_INDICES, enforced by its validation step), whose message a longer face gets.
constexpr unsigned kMaxFaceCorners = 32767;

// A vector's length without underflow or overflow of its squares.
double norm(const Point& v);
// The largest distance between two corners: the same double as the largest norm(a - b) over all
// pairs (face_shapes_reference.h), found by branch and bound over a k-d tree.
double diameter(const std::vector<Point>& corners);
// Newell's normal: twice the vector area of a planar polygon, the best plane of a bent one.
Point newell(const std::vector<Point>& corners);
// A quad kept as one patch: planar within kPlanarity, every corner turning the same way.
bool planar_convex_quad(const std::vector<Point>& q);
// Two edges of the face, projected on its best plane, that cross (edge i runs from corner i to
// corner i + 1), or none. Edges that only touch (a corner on another edge, a bridge traversed
// twice) do not cross. Of several crossing pairs, the first (i, j), i < j, in the order i then
// j. A sweep over the edges' boxes: O(n log n + pairs of edges whose boxes meet).
std::optional<std::pair<std::size_t, std::size_t>> crossing_edges(const std::vector<Point>& corners);
// Ear clipping in the face's best plane: each step clips the first corner, in the face's order,
// that is convex with no other remaining corner in its closed triangle; a fan of what is left
// when no corner is (an outline that touches itself). Triangles in the face's own winding.
std::vector<std::vector<Point>> ear_clip(const std::vector<Point>& corners);
// Triangles, in the face's own winding, of a face that is not kept as it is.
std::vector<std::vector<Point>> split(const std::vector<Point>& corners);
// Whether a face whose net area is flat still has corners that span a plane: some triangle of
// corner 0 and two consecutive corners has an area over kSpan of the diameter squared. Such
// a face folds over itself (a bow-tie of two equal halves), which is no degenerate face.
constexpr double kSpan = 1e-6;
bool spans_plane(const std::vector<Point>& corners);
// Whether a polygon's area is at most kFlat of its diameter squared (degenerate).
bool flat(const std::vector<Point>& polygon);

// The predicates that the crossing test and ear clipping share with their references: a face's
// corners projected on its best plane (Newell's normal) in the face's own units; twice the
// signed area of the triangle a b c; whether edges p-q and r-s cross (each one's ends strictly
// on both sides of the other's line); whether p is in the closed triangle a b c
// (counter-clockwise).
std::vector<glm::dvec2> in_best_plane(const std::vector<Point>& corners);
double cross2(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c);
bool edges_cross(glm::dvec2 p, glm::dvec2 q, glm::dvec2 r, glm::dvec2 s);
bool in_closed_triangle(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, glm::dvec2 p);

}  // namespace ncube::models

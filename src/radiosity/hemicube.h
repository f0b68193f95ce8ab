// The hemicube (Cohen & Greenberg 1985), placed at the shooter as in progressive refinement
// (Cohen, Chen, Wallace & Greenberg 1988): the form factors the paper's ray tracing replaced
// (section 2.1; --form-factors hemicube, docs/model.md "The hemicube").
//
// A unit hemicube stands on the shooter with its top face (N x N cells) one unit above the
// eye and four side faces of N x N/2 cells. Every receiving polygon and occluder is
// projected onto each face through the eye; each cell goes to the nearest polygon whose
// projection covers the cell's centre (the item buffer, with an inverse-depth buffer). A
// cell's delta form factor is the point-to-cell form factor at its centre:
//   top face   dA / (pi (x^2 + y^2 + 1)^2),
//   side faces z dA / (pi (y^2 + z^2 + 1)^2),
// NOT normalised: their sum over the whole hemicube is 1 only to the midpoint rule's
// accuracy (DeltaFormFactors::sum: 1 + 5.4e-5 at N = 100). A receiver's point form factor
// F(eye -> receiver) is the sum over its cells; its form factor to the shooter follows by
// reciprocity, F(receiver -> shooter) = F(shooter -> receiver) A_shooter / A_receiver.
//
// The hemicube's known errors are kept, not corrected: aliasing (a polygon covers a cell or
// not by its centre alone), the proximity error (the point-to-area form factor of the eye
// stands for the whole shooter, or the whole element with --hemicube-placement elements), and
// visibility judged from the eye only. A polygon seen from behind (the eye behind its plane)
// receives nothing; whether it takes cells is a choice (--hemicube-back-faces): it blocks
// (the default: what lies beyond it is hidden) or it is culled and passes the light on.
//
// The work is counted as the node program would do it (work_counts.h, the hemicube_*
// counters; the flop figure of each unit in platforms/cost_model.json says where it comes
// from). The rows of a polygon are scanned as a 1990 scan converter does them, two active
// edges stepped per row and the inverse depth stepped per cell; this code computes each
// row's ends and each cell's depth directly, which gives the same cells to rounding.
#pragma once

#include <string>
#include <vector>

#include "counts/work_counts.h"
#include "scene/scene.h"

namespace ncube {

// Where the shooter's hemicubes stand: one at its centre (the classic method, the default),
// or one at the centre of each of the shooter patch's elements (the scene's grid, Patch::nu
// x Patch::nv), each weighted by its element's area.
enum class HemicubePlacement { kCentre, kElements };
const char* hemicube_placement_name(HemicubePlacement placement);  // "centre", "elements"

// What a polygon seen from behind does in the hemicube: it takes cells and hides what lies
// beyond it (kBlock, the default: an opaque surface whose back is black), or it is culled
// after its facing test and takes none (kPass: the back-face culling of a renderer, which a
// surface seen from behind does not stop). It receives nothing either way: patches receive
// on their front only.
enum class HemicubeBackFaces { kBlock, kPass };
const char* hemicube_back_faces_name(HemicubeBackFaces back_faces);  // "block", "pass"

// What the shooter's reciprocity does with a factor it makes above 1. F(receiver -> shooter)
// = A_shooter F(eye -> receiver) / A_receiver comes out above 1 (no receiver can send more
// than all of its light anywhere) where a small receiver stands close in front of the eye:
// the eye's point factor stands for the whole shooter (the proximity error). kAsComputed
// (the default) keeps it, as the classic method does; kClamp takes min(1, F), a guard
// assumed here, not taken from a source (the literature's remedy for near receivers is to
// integrate over the shooter instead: receiver-centred rays, Wallace, Elmquist & Haines 1989,
// which is the paper's method). Every run counts such receivers either way
// (counts.hemicube_reciprocal_above_one).
enum class HemicubeReciprocity { kAsComputed, kClamp };
const char* hemicube_reciprocity_name(HemicubeReciprocity reciprocity);  // "as-computed", "clamp"

// N, top-face cells on a side: even (the side faces are N x N/2).
constexpr int kMinHemicubeResolution = 2;
constexpr int kMaxHemicubeResolution = 2000;
bool is_valid_hemicube_resolution(int resolution);

struct HemicubeOptions {
  int resolution = 100;  // the era's public codes (Graphics Gems II, HELIOS)
  HemicubePlacement placement = HemicubePlacement::kCentre;
  HemicubeBackFaces back_faces = HemicubeBackFaces::kBlock;
  HemicubeReciprocity reciprocity = HemicubeReciprocity::kAsComputed;
};

// The delta form factors of every cell: top[j * N + i] for the top face's cell (i, j), x and
// y from -1 to 1; side[j * N + i] for a side face's cell (i, j), across from -1 to 1 and z
// from 0 (j = 0) to 1. The four side faces share one table.
struct DeltaFormFactors {
  explicit DeltaFormFactors(int resolution);
  int resolution;
  std::vector<double> top, side;
  double sum() const;  // top + 4 x side: the whole hemicube
};

// A polygon the hemicube draws: a receiver (given cells, read out) or an occluder (given
// cells, not read out). Its depth comes from its plane (unit front `normal` through
// `plane_point`), so that pieces of one patch (its elements) and the whole patch have the
// same depth at every cell to the last bit; a cell at the same depth in two polygons goes to
// the lower `key` (the scene patch it lies on), so that a radiosity processor reads off its
// own elements what a single processor rendering every element would: the answers do not
// depend on how the patches are spread over the processors.
struct HemicubePolygon {
  Polygon polygon;
  Vec3 normal{0.0};
  Vec3 plane_point{0.0};
  double area = 0.0;  // receivers: for reciprocity
  int key = 0;
};
// A polygon standing alone: its own plane and area.
HemicubePolygon hemicube_polygon(const Polygon& polygon, int key = 0);
// `piece` (of area `area`) of the scene's patch `patch`, on the patch's plane.
HemicubePolygon hemicube_polygon(const Scene& scene, int patch, const Polygon& piece, double area);

// One hemicube with its eye at `eye`, its top face towards the unit `normal` and its first
// axis along the unit `tangent` (perpendicular to `normal`): adds `weight` x F(eye ->
// receiver k) to point_form_factors[k] for every receiver (the vector has one entry per
// receiver). `occluders` take cells too (nearer, they hide the receivers) but are not read
// out; with HemicubeBackFaces::kPass a polygon the eye sees from behind takes none. Counts
// the work.
void render_hemicube(const Vec3& eye, const Vec3& normal, const Vec3& tangent,
                     const std::vector<HemicubePolygon>& receivers,
                     const std::vector<HemicubePolygon>& occluders, const DeltaFormFactors& deltas,
                     double weight, std::vector<double>& point_form_factors, WorkCounts& counts,
                     HemicubeBackFaces back_faces = HemicubeBackFaces::kBlock);

// The form factors F(receiver k -> shooter) of the scene's patch `shooter_patch`, computed
// by its hemicube(s) over `receivers` and `occluders` (neither should hold the shooter
// itself, which is in the eye's plane and gets no cells). Any node program that holds the
// shooter's geometry can call it (the radiosity processors with V = 0, the shooter-centred
// parallelisation). Counts the work; the delta form factors' table is the node's from its
// start (hemicube_setup_work) and is not counted here.
std::vector<double> hemicube_form_factors(const Scene& scene, int shooter_patch,
                                          const std::vector<HemicubePolygon>& receivers,
                                          const std::vector<HemicubePolygon>& occluders,
                                          const HemicubeOptions& options, WorkCounts& counts);

// The work of a node computing the delta form factors' table when it starts.
WorkCounts hemicube_setup_work(const HemicubeOptions& options);

// Modeled memory of a node that renders hemicubes: the table of delta form factors and one
// face's item and depth buffers (the faces are rendered and read out one after the other).
double hemicube_table_entries(const HemicubeOptions& options);  // 1.5 N^2
double hemicube_buffer_cells(const HemicubeOptions& options);   // N^2

}  // namespace ncube

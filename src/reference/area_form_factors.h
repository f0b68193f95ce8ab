// Element-to-element form factors integrated over both ends (docs/accuracy.md): the
// reference's replacement for the two methods it judges (the paper's point-to-shooter form
// factor from each element's centre with M rays, and the hemicube at the shooter).
//   F_ij = 1/A_i  integral_i integral_j  cos(theta_i) cos(theta_j) / (pi r^2)  V(x, y)  dA_j dA_i
// Each element gets K = side x side jittered points (stratified_points.h) with fixed seeds.
// A pair of elements far apart pairs its points one to one (K rays: point k of i with point
// pi(k) of j, pi a fixed random permutation of the pair): the kernel at both ends, as
// sampled. A near pair (centres closer than kNearFactor x the sum of the elements' radii)
// is where the kernel varies most and, for elements that share an edge, is singular: sampled
// at both ends its estimate has infinite variance (row sums of a closed cube were 1-3 % short
// at K = 256). There each point x of i takes the inner integral over j in closed form
// (point_polygon_factor.h) times the share of the kernel cos cos / (pi r^2) over the K points
// y of j whose ray is unblocked (K x K rays): exact when j is wholly seen or wholly hidden.
// The double integral I_ij is computed and held once per pair (i < j), so F_ij A_i = F_ji A_j
// holds exactly. Pairs on one patch are planar: F = 0. One-sided: only fronts send and receive (a
// point behind the other element's plane takes nothing from it). A point enclosed by backs
// (the floor inside a bottomless box) sees no front: it is left out of its element's open
// area, which is what F_ij is the exchange of (open_fraction_of in the .cpp).
#pragma once

#include <cstdint>
#include <vector>

#include "scene/scene.h"

namespace ncube::reference {

struct FormFactorEntry {
  int element = 0;   // j
  double value = 0.0;  // F_ij
};

// The form factors with every pair held once: I_ij = A_i F_ij = A_j F_ji (reciprocity; the
// double integral above), j > i, in row i, 12 bytes a nonzero pair (a 32-bit index and a
// double). Both directions at 48 bytes each pair took 8 GB for scene1's 18,592 parts; once,
// about 1.2 GB. F_ij = I_ij / open_area[i] (i's open part, below), computed where it is used,
// the same double as when the rows were held both ways.
class FormFactors {
 public:
  struct Row {
    std::vector<std::int32_t> column;  // j > i, ascending
    std::vector<double> exchange;      // I_ij
  };
  FormFactors() = default;
  // From the open areas and each row's pairs (j > i, ascending, I_ij > 0).
  FormFactors(std::vector<double> open_area, std::vector<Row> rows);
  int size() const { return int(open_area_.size()); }
  double open_area(int i) const { return open_area_[std::size_t(i)]; }
  const Row& upper(int i) const { return rows_[std::size_t(i)]; }
  // F_ij (0 where the pair was not kept or i has no open area).
  double factor(int i, int j) const;
  // Row i in both directions, j ascending: the nonzero F_ij (for tests and small scenes).
  std::vector<FormFactorEntry> row(int i) const;
  // The pairs held (nonzero I_ij) and their bytes.
  long long pairs() const;
  double bytes() const;

 private:
  std::vector<double> open_area_;
  std::vector<Row> rows_;
};
struct FormFactorOptions {
  int side = 4;                  // K = side^2 points per element
  std::uint64_t seed = 1994;     // fixed: the same scene and K give the same matrix
  int threads = 0;               // host threads (0: every core); the result does not depend on it
  static constexpr double kNearFactor = 2.0;
  // Directions a side of the test of a point being enclosed (area_form_factors.cpp).
  static constexpr int kEnclosureSide = 4;
};

struct FormFactorStats {
  long long rays = 0;
  long long near_pairs = 0;
  long long pairs = 0;  // unordered pairs that face each other (tested)
};

// `open_fraction` (if given): per element, the share of its area that is open (not enclosed
// so that it sees only backs); F_ij is the exchange of i's open part, I_ij / (A_i open_i),
// and i's mean radiosity is open_i B_i + (1 - open_i) E_i (element_means in radiosity_solve.h).
FormFactors area_form_factors(const Scene& scene, const FormFactorOptions& options,
                                 FormFactorStats* stats = nullptr,
                                 std::vector<double>* open_fraction = nullptr);

}  // namespace ncube::reference

// The exact solution of the simulator's own structure (docs/accuracy.md, "The error taken
// apart"; issue 38 item 3): the same mesh and the same patch-shoots-elements-receive scheme as
// ./simulate, but exact form factors. Its converged answer is
//   B_e = E_e + rho_e sum_p F(c_e -> p) Bbar_p,   Bbar_p = sum_{e in p} (A_e / A_p) B_e,
// c_e the element's centre (the receiving point, paper section 4), Bbar_p the area-weighted
// mean radiosity a patch shoots (src/radiosity/radiosity_engine.cpp accumulates a patch's
// unshot radiosity so), and F(c -> p) = integral over p of cos cos / (pi r^2) V dA, one-sided
// (a receiver behind the shooter's plane gets nothing; the shooter is cut to the receiver's
// front half-space). What differs from a method of the simulator is the form factor alone:
// the difference of a run from this answer is its form-factor error, and this answer's
// difference from the truth is the structure's own error.
//
// F(c -> p) is computed with the reference's own code (point_polygon_factor.h, ray_visibility.h,
// stratified_points.h), not the methods': the shooter is cut into g x g cells of its bilinear
// grid; each cell contributes its closed-form unoccluded factor (Lambert's contour integral)
// times the kernel-weighted share of 2 x 2 jittered points of the cell whose Embree ray from
// c is unblocked. So K = (2g)^2 rays a pair: exact where a cell is wholly seen or wholly
// hidden, sampled (stratified) only along shadow boundaries.
//
// The structure "elements" (every element its own patch) is the same with each element
// shooting its own radiosity: point collocation at the centres with constant elements.
//
// The hemicube's own structures (docs/accuracy.md, "Each method against its own structure"):
// the hemicube does not receive at element centres; it reads a receiver off by the cells its
// whole polygon covers, seen from an eye on the shooter, and turns that point factor around by
// reciprocity. Its exact counterpart, "hemicube-centre", puts F(e -> p) = A_p F(c_p -> e) / A_e
// with c_p the shooter's centroid (the eye of --hemicube-placement centre) and F(c -> e) =
// integral over the element e of cos cos / (pi r^2) V dA, one-sided (nothing when the eye is
// behind e's plane; e cut to the eye's front half-space); "hemicube-elements" sums the same
// over an eye at each of the shooter's elements' centroids, weighted by their areas
// (--hemicube-placement elements): F(e -> p) = sum_j A_j F(c_j -> e) / A_e. Reciprocity is
// kept as the hemicube keeps it, so a factor may exceed 1 (a small receiver close in front of
// an eye). The patch still shoots its elements' mean (the same solve). F(c -> e) is the same
// reference code turned around: e cut into g x g cells, each cell's closed form times the
// kernel-weighted visible share of 2 x 2 jittered points of the cell, rays from the eye.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "scene/scene.h"

namespace ncube::reference {

enum class Structure { kPatches, kElements, kHemicubeCentre, kHemicubeElements };
// The structure of a name ("patches", "elements", "hemicube-centre", "hemicube-elements");
// false for another name.
bool structure_of(const std::string& name, Structure* structure);

struct StructureOptions {
  int side = 32;              // sqrt(K): K = side^2 visibility points a shooter; even
  std::uint64_t seed = 1994;  // fixed: the same scene and K give the same answer
  int threads = 0;            // host threads (0: every core); the result does not depend on it
};

// Row e: F(c_e -> shooter s) for the shooters s that e can see (the scene's patches, or its
// elements for Structure::kElements), s ascending.
struct StructureEntry {
  int shooter = 0;
  double value = 0.0;
};
using StructureRows = std::vector<std::vector<StructureEntry>>;

struct StructureStats {
  long long rays = 0;
  long long pairs = 0;  // (receiver, shooter) pairs that face each other
};

// The scene whose patches are the shooters of `structure`: the scene itself, or every element
// made a patch of one element (same polygon, its patch's emission and reflectance), in the
// scene's element order.
Scene shooter_scene(const Scene& scene, Structure structure);

// F(c_e -> p) for every element e of `shooters` (a scene as shooter_scene gives) and patch p.
StructureRows structure_form_factors(const Scene& shooters, const StructureOptions& options,
                                     StructureStats* stats = nullptr);

struct StructureSolve {
  std::vector<Rgb> radiosity;  // per element
  // Per patch: the share of what it sends that the elements' centres receive,
  // s_p = sum_e A_e F(c_e -> p) / A_p (1 in a closed room if the centres integrated exactly:
  // the balance's "lost by the structure" is sum_p A_p Bbar_p (1 - s_p), docs/accuracy.md).
  std::vector<double> delivery;
  int sweeps = 0;
  double last_change = 0.0;
};

// The hemicube's structures: F(e -> p) for every element e of `scene` and patch p, from an
// eye at p's centroid (kHemicubeCentre) or at each of p's elements' centroids
// (kHemicubeElements), by reciprocity (above).
StructureRows eye_form_factors(const Scene& scene, Structure structure,
                               const StructureOptions& options, StructureStats* stats = nullptr);

// Gauss-Seidel sweeps until no element's luminance changes by more than `tolerance` of the
// largest.
StructureSolve solve_structure(const Scene& shooters, const StructureRows& rows,
                               double tolerance = 1e-13, int max_sweeps = 100000);

std::string structure_name(Structure structure);

// The file (docs/accuracy.md, "The exact structure's file"): the reference file's layout
// (reference_file.h: version 1, so analysis/ncube/accuracy.py reads it as a reference) with
// "structure", the shooters' "delivery" and the self-agreement of K/4 against K; deterministic
// apart from host_seconds and code_version.
struct StructureRun {
  std::string scene_file, scene_sha256;
  Structure structure = Structure::kPatches;
  int samples = 0, check_samples = 0;
  StructureStats stats, check_stats;
  StructureSolve solve;
  double self_element_rms = 0.0, self_patch_rms = 0.0, self_patch_max = 0.0;
  int self_worst_patch = -1;
  std::vector<Rgb> check_radiosity;  // the K/4 solution, each element's luminance in the file
  // The hemicube's structures only: every (element, shooter) whose factor F(element ->
  // shooter) came out above 1 by reciprocity, with the factor (written as "above_one").
  std::vector<std::pair<int, StructureEntry>> above_one;
  double host_seconds = 0.0;
};

std::string structure_text(const Scene& scene, const StructureRun& run);

// The entries of `rows` above 1, (element, entry) in element order.
std::vector<std::pair<int, StructureEntry>> entries_above_one(const StructureRows& rows);

}  // namespace ncube::reference

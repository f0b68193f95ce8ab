// Form factor from a differential receiving area to a polygon, by the analytic contour
// integral (Lambert; Wallace 1989, as used in the paper's section 2.2). Exact for any
// distance, so elements close to the shooter get accurate values.
#pragma once

#include <cstdint>
#include <vector>

#include "counts/work_counts.h"
#include "geometry/polygon.h"
#include "visibility/shooter.h"

namespace ncube {

// F(dA -> polygon) for a point with unit normal `normal`. The polygon is first clipped to
// the half-space in front of the point (only what lies above the receiver's tangent plane
// is seen), then F = 1/(2 pi) * |sum_k angle(r_k, r_k+1) * normal . unit(r_k x r_k+1)|.
double point_to_polygon_form_factor(const Vec3& point, const Vec3& normal,
                                    const Polygon& polygon);

// Sum of F(dA -> part) over the shooter's parts marked in `mask` (bit p: part p), each part
// as point_to_polygon_form_factor sees it. When no part needs clipping (every corner of the
// grid lies on or in front of the receiver's tangent plane), the parts' contours share
// their inner edges with opposite directions, whose terms cancel exactly; the sum then runs
// over the edges of the visible region's outline only, each edge's term computed as the
// per-part sum computes it (same to about 1e-15 relative; docs/performance.md).
double visible_parts_form_factor(const Vec3& point, const Vec3& normal, const Shooter& shooter,
                                 PartMask mask);

// The edge terms visible_parts_form_factor sums for the same question (the host work counter
// form_factor_edge_terms, work_counts.h): the visible region's contour edges when no part
// needs clipping, else each visible part's edges after clipping. Geometry only, no arctangent.
std::uint64_t form_factor_edge_terms(const Vec3& point, const Vec3& normal, const Shooter& shooter,
                                     PartMask mask);

class RadiosityEngine;
class OccluderSet;
struct ElementRef;

// The paper's ray-traced form factors (section 2.2) from `shooter` to each of `engine`'s
// `receivers` (in order): visibility by one ray from the receiver's centre to each of the
// shooter's M parts against the patches of `occluders`, then the analytic point-to-polygon
// form factor of the visible parts (zero for a receiver behind the shooter's plane). Adds
// the rays' counts and one `form_factors` per visible part that lights the receiver, as the
// paper's program counts them; adds no light. The form-factor step of a node program that
// takes a shooter's form factors to every element it holds (nodes/shooter_processor.cpp).
std::vector<double> ray_traced_form_factors(RadiosityEngine& engine, const OccluderSet& occluders,
                                            const std::vector<ElementRef>& receivers,
                                            const Shooter& shooter, WorkCounts& counts);

}  // namespace ncube

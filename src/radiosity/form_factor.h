// Form factor from a differential receiving area to a polygon, by the analytic contour
// integral (Lambert; Wallace 1989, as used in the paper's section 2.2). Exact for any
// distance, so elements close to the shooter get accurate values.
#pragma once

#include "geometry/polygon.h"
#include "radiosity/shooter.h"

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

}  // namespace ncube

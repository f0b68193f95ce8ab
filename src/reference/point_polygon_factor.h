// The unoccluded form factor from a point to a polygon by Lambert's contour integral,
// written here again (not src/radiosity/form_factor.h) so that the reference shares no code
// with the method it judges: F = 1/(2 pi) |sum over edges of gamma_k n . unit(r_k x r_k+1)|,
// the polygon first cut to the half-space in front of the point's tangent plane.
#pragma once

#include "geometry/polygon.h"

namespace ncube::reference {

double point_polygon_factor(const Vec3& point, const Vec3& normal, const Polygon& polygon);

}  // namespace ncube::reference

// Total squared curvature of a filling surface over its trimmed region,
//   E = ∫∫_trim (κ1² + κ2²) dA,
// the intrinsic bending energy (a thin plate's, Willmore-like), the same whatever the domain
// and parameterization: unlike the fairness energy of fairness_energy.h, whose value depends on
// the (u, v) scale of each parameterizer's domain, it can rank fills of one hole made with
// different parameterizers (fill by result, issue 20). Evaluated by the midpoint rule on a
// grid over the domain, cells whose centre lies inside the trim polygon; dimensionless when
// the surface is in the normalized solve units (hole diagonal = 1).
#pragma once

#include "geometry/bspline_surface.h"
#include "geometry/polygon2d.h"

namespace holefill {

double trimmedBendingEnergy(const BSplineSurface& surface, const Polygon2& trim, int grid = 40);

}  // namespace holefill

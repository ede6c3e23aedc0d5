// Tensor-product Bézier patches as the one-span case of BSplineSurface (knots {0…0, 1…1}),
// so evaluation and derivatives are BSplineSurface's; here only what Bézier patches add:
// exact degree elevation (Farin, "Curves and Surfaces for CAGD", 5th ed., sec. 6.1 applied
// per row and column) and de Casteljau subdivision at a parameter. The G² G-NURBS
// construction (g2-gnurbs.md sec. 2) elevates the bicubic patches of EP 1-rings to degree 5
// and splits each into 2×2 sub-patches.
#pragma once

#include <array>

#include "geometry/bspline_surface.h"

namespace holefill {

// A Bézier patch of the given degrees; poles row-major, index i*(degreeV+1)+j, i along u.
BSplineSurface bezierPatch(int degreeU, int degreeV, const Eigen::MatrixX3d& poles);
bool isBezierPatch(const BSplineSurface& s);

// The same surface at degrees (degreeU, degreeV), each at least the patch's own.
BSplineSurface elevateBezier(const BSplineSurface& patch, int degreeU, int degreeV);

// The four sub-patches over [0,u]×[0,v], [u,1]×[0,v], [0,u]×[v,1], [u,1]×[v,1], each
// reparameterized to [0,1]²; index = (upper v half ? 2 : 0) + (upper u half ? 1 : 0).
std::array<BSplineSurface, 4> splitBezier(const BSplineSurface& patch, double u = 0.5, double v = 0.5);

}  // namespace holefill

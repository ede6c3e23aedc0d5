// A THB-spline fit exported as a set of faces (bidgcn.md sec. 5; the alternative to the single
// finest-level B-spline): one face per cell of the hierarchical mesh, each the finest-level
// surface restricted to the cell's parameter rectangle, sewn into one shell. The shell shows
// the refinement in any CAD viewer (large faces where the fit is coarse) and is geometrically
// the same surface, so neighbouring faces meet exactly.
#pragma once

#include <TopoDS_Shape.hxx>

#include "fitting/thb_spline.h"
#include "geometry/bspline_surface.h"

namespace holefill {

// Throws Error when a face cannot be built or the faces do not sew into one shell.
TopoDS_Shape thbCellFaces(const ThbSpace& space, const BSplineSurface& surface);

}  // namespace holefill

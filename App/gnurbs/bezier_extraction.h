// The guidance surface of G² G-NURBS by generalized Bézier extraction (g2-gnurbs.md sec. 2,
// after Feng et al., "Patching non-uniform extraordinary points", 2024): one bicubic Bézier
// patch per cage face from face points (knot-interval weighted bilinear combinations of the
// face's corners, eq. before (1)), edge points (knot-interval weighted averages of the face
// points across an edge, eq. (1)) and vertex points (eq. (2): Σ d_{i-1} d_{i+2} F_i / Σ, which
// is eq. (1) at a regular vertex and the EP rule elsewhere). Over a regular, tensor-product
// region this is exactly the cubic B-spline of the cage with those knot intervals, so the
// surface is C² outside EP 1-rings and only C0 across their spoke edges.
// Beyond the paper's text, which is silent on them: cage-boundary and sharp edges are both
// feature lines. The patches on each side take the line as their border, its Bézier points
// coming from the cubic B-spline of the line's own polyline (so the two sides meet exactly, C0);
// a vertex where a line ends, turns into a boundary corner or meets other lines is interpolated.
// Face points next to a feature line see the face mirrored across it (the phantom-face rule
// that makes a regular cage boundary the natural-end B-spline). An anchor replaces the vertex
// point of its EP (sec. 5.1, eq. (23)).
#pragma once

#include <vector>

#include "geometry/bspline_surface.h"
#include "gnurbs/quad_cage.h"

namespace holefill {

struct GuidanceSurface {
  // Per cage face, a bicubic Bézier patch (bezier_patch.h) with corner quads(f,0) at (0,0),
  // u along quads(f,0) → quads(f,1) and v along quads(f,0) → quads(f,3).
  std::vector<BSplineSurface> patches;
  std::vector<Eigen::Vector3d> vertexPoints;  // per cage vertex, the patches' common corner
};

GuidanceSurface extractGuidanceSurface(const QuadCage& cage, const CageTopology& topology);

}  // namespace holefill

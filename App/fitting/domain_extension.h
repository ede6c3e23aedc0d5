// Extension of a parameterized trimmed region to its whole domain rectangle (mesh-extension.md
// sec. 5): in 2D, regular grid samples of the (optionally enlarged) rectangle outside the
// region's parameter footprint, inner holes included, triangulated together with the region's
// boundary edges as constraints (CGAL's constrained Delaunay triangulation); in 3D, the new
// vertices placed by the polyharmonic extension Δᵏx = 0 (k = 2 continues the region G1, k = 3 G2,
// the default), with the region's own vertices fixed and Δ = M⁻¹L (cotangent Laplacian over
// mixed Voronoi areas, the five-point stencil on the grid), plus (k+1)-th differences along the
// new grid lines (the paper's isocurve fairness), one sparse least-squares problem. It is solved
// on the grid padded by k + 1 layers beyond the rectangle and cropped back, so that where the
// region's labeled sides lie on the rectangle's rim the new vertices next to them still have
// whole stencils. On a grid through the region's vertices a bicubic is continued exactly (k = 3).
// The paper's mesh fairness (smoothness of ARAP distortions between neighbouring triangles) is an
// option, off by default. The cotangent Laplacian wants a fair triangulation of the region: on
// cells of 3.3:1 aspect the bundled torus region's extension curled (data max 5.2e-3), on square
// cells it is calm (3.9e-4).
#pragma once

#include <Eigen/Dense>

#include "mesh/triangle_mesh.h"

namespace holefill {

struct DomainExtensionOptions {
  double spacing = 0;      // grid spacing in the domain; 0: the region's mean edge length in uv
  int marginLayers = 0;    // grid layers added around the rectangle
  // Width added around the rectangle in domain units, at least (the larger of it and
  // marginLayers layers): a margin that stays put when the grid is rebuilt finer.
  double marginWidth = 0;
  // Least distance of the new samples from the region's boundary in the domain; 0: half the
  // spacing (no slivers). A grid finer than the region's edges keeps the first grid's clearance:
  // samples closer in sit where the region's own vertices already decide the surface.
  double clearance = 0;
  int order = 3;           // k of Δᵏx = 0: 2 (G1) or 3 (G2)
  double fairness = 1e-2;  // weight of the (k+1)-th differences along the new grid lines, relative to Δᵏ's
  // The paper's isocurve fairness instead (sec. 5.2.2.1): k-th differences along the extension's
  // four boundaries and the isocurves through the rectangle's (labeled) sides only, at the same
  // weight; the grid lines of the padding beyond the domain keep theirs. For comparison.
  bool paperIsocurves = false;
  // Weight holding the region's vertices within k rings of its boundary to their places, relative
  // to Δᵏ's (0: fixed exactly, the paper's choice); below 1, scan noise is not amplified outward.
  double boundaryFidelity = 1e-3;
  // Weight of the paper's mesh fairness (differences of the ARAP distortions of neighbouring
  // triangles, rotations from a first solve without it), relative to Δᵏ's; 0 leaves it out.
  double meshFairness = 0;
  // False: the domain's new samples and triangles only, their positions left for the caller to
  // place (labeled_fit's extension sampled from a thin-plate fit), without solving Δᵏx = 0 — a
  // solve it would throw away, and the one part whose cost grows past the region's own (found
  // by fuzzing: 19 s on a stretched map of 1,140 vertices, past the 120 s limit under the sanitizers).
  bool continueSurface = true;
};

struct DomainExtension {
  TriangleMesh mesh;             // the region's vertices and triangles first, unchanged, then the new ones
  Eigen::MatrixX2d uv;           // per vertex of `mesh`
  int regionVertices = 0, regionTriangles = 0;
  double u0 = 0, v0 = 0, u1 = 0, v1 = 0;  // the extended domain
  double spacing = 0;                     // of the new samples' grid (the larger of its two steps)
};

// `uv` per region vertex (e.g. LabeledParameterization::uv), inside [0, width] × [0, height]
// give or take the free boundary stretches. Throws Error for sizes that disagree, non-finite uv
// or an order other than 2 or 3.
DomainExtension extendToRectangle(const TriangleMesh& region, const Eigen::MatrixX2d& uv, double width, double height,
                                  const DomainExtensionOptions& options = {});

}  // namespace holefill

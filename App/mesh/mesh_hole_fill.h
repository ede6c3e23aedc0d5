// Filling the holes of a triangle mesh by the pipeline of Hu et al., "Filling Holes in
// Triangular Meshes in Engineering": detection (mesh_holes.h), triangulation by the modified
// minimum-angle principle (min_angle_triangulation.h), density refinement with Delaunay-like
// relaxation (patch_refinement.h) and bilateral fairing of the new vertices
// (bilateral_fairing.h). Only vertices and triangles are added: the input's vertices and
// triangles come first in the result, bit for bit and in their order (after the weld of
// coincident vertices, vertex_weld.h, where MeshFillOptions::weld asks for it). Each hole is filled
// on its own; one that cannot be filled is reported and left open, the rest still are.
// The per-hole report has the columns of the paper's Table 1 (new vertices and triangles,
// Field's quality min/max/mean) plus time.
#pragma once

#include "geometry/outcome.h"

#include <functional>
#include <string>
#include <vector>

#include "mesh/bilateral_fairing.h"
#include "mesh/mesh_holes.h"
#include "mesh/laplacian_fairing.h"
#include "mesh/min_angle_triangulation.h"
#include "mesh/min_dihedral_triangulation.h"
#include "mesh/patch_refinement.h"
#include "mesh/quality_improvement.h"
#include "mesh/vertex_weld.h"

namespace holefill {

struct MeshFillOptions {
  // Holes with more boundary vertices stay open, with a message saying so (0: no limit). The fill's
  // cost grows faster than the boundary (the fairing's sparse LU): a 5,000-vertex hole takes 2 s on
  // one core, a 20,000-vertex one about a minute, and a hole that long is mostly a scan's outer
  // border, which nobody means to close. One default for every door (CLI, Python, task panel).
  int maxBoundary = 5000;
  // > 0: vertices closer than this fraction of the bounding-box diagonal are merged first
  // (vertex_weld.h), so that seams of duplicated vertices close and only the real holes are
  // found and filled; hole indices then refer to the welded mesh. 0: the mesh as it is.
  double weld = 0;
  std::vector<int> holes;                // indices into findMeshHoles(mesh).holes; empty: every fillable hole
  bool refine = true;                    // density refinement (off: the bare minimum-angle triangulation)
  // The initial triangulation: the paper's minimum-angle ear cutting, Liepa's minimum-dihedral
  // dynamic program (the CGAL peer's; loops longer than maxDihedralLoop fall back to minimum
  // angle, the program being cubic), or per hole: minimum angle where a crease of the
  // surrounding mesh (dihedral above creaseAngle) reaches the loop, minimum dihedral elsewhere.
  enum class Triangulation { MinAngle, MinDihedral, Auto } initial = Triangulation::MinAngle;
  int maxDihedralLoop = 400;
  // Our addition: each hole's patch is tested exactly for triangles crossing each other, the
  // surface around the hole or earlier holes' patches (self_intersection.h); where one does, the
  // hole is filled again step by step plainer (no bilateral filter; flat placement; the bare
  // triangulation; the other initial triangulation, bare) until none crosses, the report saying
  // which (MeshHoleFill::fallback). false: the paper's pipeline as it is.
  bool checkCrossings = true;
  double creaseAngle = 60.0 * M_PI / 180;
  bool keepBetterBare = true;            // a planar hole keeps its bare triangulation when that has the better
                                         // worst triangle (a removed sliver, a 3-vertex gap)
  MinAngleOptions triangulation;
  RefinementOptions refinement;
  QualityOptions quality;                // our addition between refinement and fairing: smoothing and splits (see its header)
  // Our placement of the new vertices, Δ^k x = 0 (see its header), at k = 3 (minimum variation),
  // and the paper's bilateral filter off (fairing.iterations 0; paperPipeline sets it as the paper
  // does). Measured on the 96 cut cases of the mesh-hole corpus (tests/corpus/mesh_holes.py,
  // docs/benchmarks.md, issue 26): median RMS distance to the cut-away surface 7.2e-3 of the
  // diagonal with the thin plate and 3 bilateral iterations (issue 5's default), 4.6e-3 without
  // the filter, 3.8e-3 at k = 3 without it (CGAL's 5.7e-3), lower in each of the six classes;
  // valid fills (111 of 138) and triangle quality (q mean 0.88) the same.
  LaplacianFairingOptions shape = [] {
    LaplacianFairingOptions s;
    s.order = 3;
    return s;
  }();
  BilateralOptions fairing = [] {
    BilateralOptions b;
    b.iterations = 0;
    return b;
  }();
  std::function<bool(double)> progress;  // fraction in [0,1]; return false to cancel (filled holes are kept)
};

struct MeshHoleFill {
  int hole = -1;                         // index into MeshFillResult::detection.holes
  int boundaryVertices = 0;
  double length = 0;
  bool filled = false;
  std::string message;                   // why not, or notes from detection
  int newVertices = 0, newTriangles = 0;
  double minQuality = 0, maxQuality = 0, meanQuality = 0;
  double goodShare = 0;                  // share of new triangles with quality ≥ 0.7
  double sigma = 0;                      // the triangulation's normal threshold (radians)
  std::string triangulation;             // "angle", "dihedral" or "fan" (from a new centre vertex, where both others
                                         // would repeat an edge the mesh has): the one used
  std::string fallback;                  // the plainer fill kept where the first crossed (checkCrossings); "" none
  int crossings = -1;                    // pairs of triangles still crossing in the kept patch; -1: not checked
  int splits = 0, swaps = 0;
  double seconds = 0;
};

struct MeshFillResult {
  TriangleMesh mesh;                     // input first, bit for bit, then the new vertices and triangles
  MeshHoleReport detection;
  std::vector<MeshHoleFill> fills;       // one per detected hole, in detection order
  int filledHoles = 0, openHoles = 0;    // open: detected and not filled (skipped, failed or not asked for)
  bool closed = false;                   // no boundary edge left
  bool closedWhenWelded = false;         // no boundary edge left once coincident (duplicated) vertices are welded
  bool cancelled = false;
  int weldedVertices = 0;                // merged into a coincident copy first (MeshFillOptions::weld)
  int droppedTriangles = 0;              // collapsed or repeated by that merge
  double seconds = 0;
  std::vector<std::string> warnings;
  // Failed when no hole was filled and one is left open, Warned when some are left open
  // (faulting: their detection indices), Cancelled, else Ok.
  Outcome outcome() const;
  std::string toJson() const;
};

// The paper's pipeline exactly (Hu et al., for comparing with its Table 1 like for like): its
// minimum-angle triangulation, density refinement, flat placement (no thin-plate shape), no
// quality passes, its bilateral filter with σ_c = 0.1·d_v and σ_s = 0.5·d_v as it sets them (see
// bilateral_fairing.h on why ours reads σ_c otherwise), 3 iterations; none of our additions (no
// bare-triangulation shortcut, no crossing check). `o`'s holes, limits, weld and progress are kept.
MeshFillOptions paperPipeline(MeshFillOptions o = {});
// Whether `o` is that pipeline (the doors' mode "paper"; "ours" otherwise).
bool isPaperPipeline(const MeshFillOptions& o);

// Throws holefill::Error for an invalid mesh (NaN, bad indices), an empty one, a hole index
// out of range; broken topology only leaves the affected holes open, with a message.
MeshFillResult fillMeshHoles(const TriangleMesh& mesh, const MeshFillOptions& options = {});

}  // namespace holefill

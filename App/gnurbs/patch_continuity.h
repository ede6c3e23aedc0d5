// Continuity of a surface over a quad cage across its cage edges, the measure the G² G-NURBS
// tests and benchmark apply to our surface and to a peer's (OpenSubdiv's limit surface) alike.
// Each interior cage edge is sampled at evenly spaced parameters, ends included; at each
// sample the two faces' jets give, as DESIGN.md defines them for patch boundaries,
//   G0 = |S_f − S_g|,  G1 = angle(n_f, n_g),  G2 = |κ_f − κ_g| / max(|κ_g|, 1/scale),
// κ the normal curvature across the edge (along n_f × edge tangent, both signed by n_f).
#pragma once

#include <functional>
#include <vector>

#include "geometry/differential_geometry.h"
#include "gnurbs/quad_cage.h"

namespace holefill {

// Position and derivatives of the surface over face f at its parameters (u, v) ∈ [0,1]², u along
// quads(f,0) → quads(f,1) and v along quads(f,0) → quads(f,3).
using FaceJetFunction = std::function<SurfaceJet(int face, double u, double v)>;

struct CageEdgeContinuity {
  int a = -1, b = -1;            // cage vertices of the edge
  bool sharp = false;            // a crease: only G0 is meaningful
  bool nearEP = false;           // the edge has an extraordinary point at an end (a spoke edge)
  double g0 = 0, g1 = 0, g2 = 0; // maxima over the samples
  double maxCurvature = 0;       // max |κ| across the edge over the samples, both sides
  int singularSamples = 0;       // samples where a normal was undefined (skipped)
};

// One entry per interior cage edge, in increasing (min, max) vertex order.
std::vector<CageEdgeContinuity> cageEdgeContinuity(const QuadCage& cage, const CageTopology& topology,
                                                   const FaceJetFunction& jet, int samplesPerEdge, double scale);

}  // namespace holefill

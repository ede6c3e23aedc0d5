// What a G-NURBS build reports to its users (CLI --json, Python, the FreeCAD object): the
// construction's diagnostics and the continuity it reached, measured with cageEdgeContinuity
// over every interior cage edge (DESIGN.md's G1/G2), near EPs (spoke edges) and elsewhere.
#pragma once

#include <string>

#include "gnurbs/g2_gnurbs.h"
#include "gnurbs/gnurbs_brep.h"
#include "geometry/outcome.h"
#include "gnurbs/gnurbs_fit.h"

namespace holefill {

struct GnurbsContinuity {
  int edges = 0, spokeEdges = 0, sharpEdges = 0;
  double g0 = 0;                        // max over all edges, / bounding-box diagonal
  double g1Spokes = 0, g2Spokes = 0;    // max over spoke edges (radians, relative)
  double g1Elsewhere = 0, g2Elsewhere = 0;
  double maxCurvatureNearEPs = 0;       // max |κ| across spoke edges, × diagonal
  int singularSamples = 0;
};

// Over any surface on the cage given by its face jets (ours, or a peer's for the benchmark).
GnurbsContinuity measureCageContinuity(const QuadCage& cage, const FaceJetFunction& jet, int samplesPerEdge = 21);
GnurbsContinuity measureGnurbsContinuity(const G2GnurbsResult& result, int samplesPerEdge = 21);

// `fit`: the distances of a fit to a target (gnurbs_fit.h), reported under "fit"; null for a build.
// `outcome`: the build's status (gnurbs_build.h), first in the report; null leaves it out.
std::string gnurbsReportJson(const G2GnurbsResult& result, const GnurbsContinuity& continuity, const GnurbsBrep* brep,
                             double seconds, const GnurbsFitResult* fit = nullptr, const Outcome* outcome = nullptr);

}  // namespace holefill

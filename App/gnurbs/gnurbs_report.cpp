#include "gnurbs/gnurbs_report.h"

#include <algorithm>

#include "geometry/json_writer.h"

namespace holefill {

GnurbsContinuity measureGnurbsContinuity(const G2GnurbsResult& result, int samplesPerEdge) {
  return measureCageContinuity(result.cage, faceJets(result), samplesPerEdge);
}

GnurbsContinuity measureCageContinuity(const QuadCage& cage, const FaceJetFunction& jet, int samplesPerEdge) {
  const Eigen::MatrixX3d& V = cage.vertices;
  const double diagonal = std::max((V.colwise().maxCoeff() - V.colwise().minCoeff()).norm(), 1e-300);
  GnurbsContinuity c;
  for (const auto& e : cageEdgeContinuity(cage, CageTopology(cage), jet, samplesPerEdge, diagonal)) {
    ++c.edges;
    c.g0 = std::max(c.g0, e.g0 / diagonal);
    c.singularSamples += e.singularSamples;
    if (e.sharp) {
      ++c.sharpEdges;
      continue;
    }
    if (e.nearEP) {
      ++c.spokeEdges;
      c.g1Spokes = std::max(c.g1Spokes, e.g1);
      c.g2Spokes = std::max(c.g2Spokes, e.g2);
      c.maxCurvatureNearEPs = std::max(c.maxCurvatureNearEPs, e.maxCurvature * diagonal);
    } else {
      c.g1Elsewhere = std::max(c.g1Elsewhere, e.g1);
      c.g2Elsewhere = std::max(c.g2Elsewhere, e.g2);
    }
  }
  return c;
}

std::string gnurbsReportJson(const G2GnurbsResult& r, const GnurbsContinuity& c, const GnurbsBrep* brep, double seconds, const GnurbsFitResult* fit,
                             const Outcome* outcome) {
  JsonWriter j;
  j.beginObject();
  if (outcome) writeOutcomeFields(j, *outcome);
  j.field("cage_vertices", static_cast<int>(r.cage.vertices.rows()))
      .field("cage_faces", static_cast<int>(r.cage.quads.rows()))
      .field("refinements", r.refinements)
      .field("refinement_reason", r.refinementReason)
      .field("extraordinary_points", r.extraordinaryPoints)
      .field("irregular_faces", r.irregularFaces)
      .field("clusters", r.clusters)
      .field("patches", static_cast<int>(r.patches.size()))
      .field("constraint_residual", r.constraintResidual)
      .field("infeasibility", r.infeasibility)
      .key("continuity")
      .beginObject()
      .field("edges", c.edges)
      .field("spoke_edges", c.spokeEdges)
      .field("sharp_edges", c.sharpEdges)
      .field("g0_relative", c.g0)
      .field("g1_spokes", c.g1Spokes)
      .field("g2_spokes", c.g2Spokes)
      .field("g1_elsewhere", c.g1Elsewhere)
      .field("g2_elsewhere", c.g2Elsewhere)
      .field("max_curvature_near_eps", c.maxCurvatureNearEPs)
      .field("singular_samples", c.singularSamples)
      .endObject();
  if (brep) {
    j.key("brep")
        .beginObject()
        .field("faces", brep->faces)
        .field("free_edges", brep->freeEdges)
        .field("closed", brep->closed)
        .field("valid", brep->valid)
        .endObject();
  }
  if (fit) {
    j.key("fit")
        .beginObject()
        .field("points", fit->points)
        .field("variables", fit->variables)
        .field("d_max_percent", 100 * fit->dMax)
        .field("d_avg_percent", 100 * fit->dAvg)
        .field("sharp_points", fit->sharpPoints)
        .field("d_max_sharp_percent", 100 * fit->dMaxSharp)
        .field("d_avg_sharp_percent", 100 * fit->dAvgSharp)
        .field("seconds", fit->seconds)
        .endObject();
  }
  j.field("seconds", seconds).field("warnings", r.warnings).endObject();
  return j.str();
}

}  // namespace holefill

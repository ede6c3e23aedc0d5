// Face building and sewing: the filling surface becomes a trimmed TopoDS_Face
// whose outer wire REUSES the hole's own edges (a pcurve on the new surface is
// added to each), so it shares those edges with the model and sews exactly; the
// face and the faces connected to it form a new shell, and a solid when that
// shell closes. Edge and vertex tolerances are raised to the measured distance
// between each edge's 3D curve and its new curve on surface, never lowered.
//
// The model passed in must be the caller's private copy: adding pcurves changes
// the shared edges (FillHole works on a BRepBuilderAPI_Copy of the user's shape).
// A face can be taken off its edges again (detachFace: pcurves removed, tolerances
// put back) and put back on (attachFace), so that several candidate faces can be
// built and judged on the same edges, one at a time, and only the one kept stays.
#pragma once

#include <Eigen/Dense>
#include <Geom2d_Curve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TopoDS_Vertex.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>
#include <vector>

#include "brep/boundary_sampling.h"
#include "brep/hole_detection.h"

namespace holefill {

struct FaceBuildResult {
  TopoDS_Face face;
  double maxEdgeDeviation = 0.0;  // max |C(t) - S(pcurve(t))| over dense checks (model units)
  // What the build put on the hole's edges (per hole edge), and the tolerances it found there.
  std::vector<Handle(Geom2d_Curve)> pcurves;
  std::vector<double> edgeTolerances, priorEdgeTolerances;
  std::vector<std::pair<TopoDS_Vertex, double>> priorVertexTolerances;
};

// uv[k] is the (model-domain) pcurve point of samples[k]; one pcurve per edge interpolates them in t.
FaceBuildResult buildTrimmedFace(const Hole& hole, const Handle(Geom_BSplineSurface)& surface,
                                 const std::vector<BoundarySample>& samples, const std::vector<Eigen::Vector2d>& uv);

// Takes the face off the hole's edges: its pcurves removed, edge and vertex tolerances as they
// were before buildTrimmedFace (only valid while no other face was built on them since).
void detachFace(const Hole& hole, const FaceBuildResult& built);
// Puts a detached face back: its pcurves and the tolerances its build set.
void attachFace(const Hole& hole, const FaceBuildResult& built);

struct SewResult {
  TopoDS_Shape shape;      // the model with the face added: shell, solid, or compound when the model had other parts
  bool closedSolid = false;
  double volume = 0.0;     // when closedSolid and computeVolume
};

// computeVolume: the volume of a closed result (a whole-model integration: on a 1.5 MB model it
// costs more than the fill, so only when asked).
SewResult sewFace(const TopoDS_Shape& model, const TopoDS_Face& face, bool computeVolume = false);

}  // namespace holefill

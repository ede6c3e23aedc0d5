// A G-NURBS surface as B-rep (issue 6's export): one face per patch (the bicubic patch of a
// regular control face, or each of the four biquintic sub-patches of a face in an EP 1-ring),
// sewn into one shell whose faces are in control-face order, a face's sub-patches in
// splitBezier order. The sidecar lists, for every B-rep face (FreeCAD's Face1, Face2, …), its
// control face and sub-patch, so a user can go from a face of the result to the cage and back.
#pragma once

#include <TopoDS_Shape.hxx>
#include <string>

#include "gnurbs/g2_gnurbs.h"

namespace holefill {

struct GnurbsBrepOptions {
  double sewTolerance = 1e-7;  // relative to the cage's bounding-box diagonal
};

struct GnurbsBrep {
  TopoDS_Shape shape;      // a shell (closed when the cage is)
  int faces = 0;
  int freeEdges = 0;       // edges used by one face only: the cage boundary's images
  bool closed = false;
  bool valid = false;      // BRepCheck_Analyzer
  std::string sidecarJson; // {"faces": [{"name": "Face1", "control_face": f, "sub_patch": s, "input_face": g}, …], …}
};

GnurbsBrep gnurbsToBrep(const G2GnurbsResult& result, const GnurbsBrepOptions& options = {});

}  // namespace holefill

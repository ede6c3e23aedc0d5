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
  // Merge rectangles of regular faces (bicubic patches of one tensor-product region) into one
  // B-spline face each, its interior knots reduced to the surface's continuity (C² where the
  // knot intervals along the rectangle's rows and columns agree). Fewer, larger faces for
  // downstream CAD; off by default so B-rep faces map one-to-one to patches.
  bool mergeRegular = false;
};

struct GnurbsBrep {
  TopoDS_Shape shape;      // a shell (closed when the cage is)
  int faces = 0;
  int freeEdges = 0;       // edges used by one face only: the cage boundary's images
  bool closed = false;
  bool valid = false;      // BRepCheck_Analyzer
  std::string sidecarJson; // {"faces": [{"name": "Face1", "control_face": f, "sub_patch": s, "input_face": g}, …], …};
                           // a merged face lists all its control faces in "control_faces"
  int mergedFaces = 0;     // B-rep faces that hold more than one patch
};

GnurbsBrep gnurbsToBrep(const G2GnurbsResult& result, const GnurbsBrepOptions& options = {});

}  // namespace holefill

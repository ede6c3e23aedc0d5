#include "fitting/point_cloud_fit.h"

#include <BRepBuilderAPI_MakeFace.hxx>
#include <cstdio>

#include "brep/thb_faces.h"
#include "fitting/cloud_boundary.h"
#include "geometry/error.h"
#include "geometry/json_writer.h"
#include "geometry/occt_bridge.h"
#include "mesh/triangle_mesh.h"

namespace holefill {

CloudBoundaryCompletion completeCloudBoundary(FlaggedCloud& c, const std::vector<int>& corners, bool rechord) {
  CloudBoundaryCompletion done;
  if (!c.flagsGiven) {
    const CloudBoundary b = detectCloudBoundary(c.points);
    c.boundary = b.boundary;
    c.flagsGiven = true;
    c.boundaryUVGiven = false;
    done.found = b.count;
    done.spacing = b.spacing;
  }
  if (!c.boundaryUVGiven || rechord) {
    c.uv = boundaryChordParameters(c.points, c.boundary, corners);
    c.boundaryUVGiven = true;
    done.chord = true;
  }
  return done;
}

PointCloudFitResult fitPointCloud(const FlaggedCloud& cloud, const PointCloudFitOptions& o) {
  ThbFitOptions f = o.fit;
  if (f.degree < 1 || f.degree > 7) throw Error("the degree must be 1 to 7");
  if (!(f.relativeTolerance > 0)) throw Error("the relative tolerance must be positive");
  if (!(o.tolerance >= 0)) throw Error("the tolerance must be zero (the relative tolerance) or positive");
  if (f.baseCells < 1) throw Error("the base space needs at least one cell a direction");
  if (f.maxIterations < 1) throw Error("the fit needs at least one iteration");
  PointCloudFitResult r;
  r.cloud = cloud;
  r.completion = completeCloudBoundary(r.cloud, o.corners);
  r.parameterization = parameterizeCloud(r.cloud.points, r.cloud.boundary, r.cloud.uv, o.parameterization);
  if (!o.adaptive) f.maxLevels = 1;
  if (const double diagonal = boundingDiagonal(r.cloud.points); o.tolerance > 0 && diagonal > 0) f.relativeTolerance = o.tolerance / diagonal;
  r.fit = fitThb(r.cloud.points, r.parameterization.uv, f);
  r.shape = o.cellFaces ? thbCellFaces(r.fit.space, r.fit.surface) : TopoDS_Shape(BRepBuilderAPI_MakeFace(toOcct(r.fit.surface), 1e-7).Face());
  return r;
}

std::vector<std::string> PointCloudFitResult::warnings() const {
  std::vector<std::string> w = parameterization.warnings;
  if (fit.folds > 0)
    w.push_back("the surface folds at " + std::to_string(fit.folds) +
                " of 4225 domain samples (crowded or crossing parameters): try the shape-preserving parameterization");
  return w;
}

Outcome PointCloudFitResult::outcome() const {
  Outcome o;
  o.warnings = warnings();
  o.status = fit.metTolerance ? Status::Ok : Status::Warned;
  char line[120];
  std::snprintf(line, sizeof line, "%s after %zu iterations: max error %.2e of the diagonal", fit.metTolerance ? "tolerance met" : "tolerance NOT met",
                fit.history.size(), fit.history.empty() ? 0.0 : fit.history.back().maxError);
  o.message = line;
  return o;
}

std::string PointCloudFitResult::toJson() const {
  JsonWriter j;
  j.beginObject();
  writeOutcomeFields(j, outcome());
  j.key("parameterization").raw(parameterization.toJson()).field("boundary_found", completion.found);
  fit.writeFields(j);
  j.field("warnings", warnings()).endObject();
  return j.str();
}

}  // namespace holefill

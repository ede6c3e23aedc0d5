// The G-NURBS pipeline as every door runs it (g2-gnurbs.md secs. 3–5): a quad cage in, the G²
// surface over it (built, or fitted to a target point set first, sec. 5.2), its B-rep shell with
// the face sidecar, and the continuity measured over the cage edges, out — one call, so that the
// CLI, the Python module and the FreeCAD object only convert arguments and results. A build is
// sound when the shell is valid and the construction left no warning; an invalid shell is still
// returned (to look at), never passed as a success.
#pragma once

#include <Eigen/Dense>
#include <optional>

#include "geometry/outcome.h"
#include <string>

#include "gnurbs/g2_gnurbs.h"
#include "gnurbs/gnurbs_brep.h"
#include "gnurbs/gnurbs_fit.h"
#include "gnurbs/gnurbs_report.h"

namespace holefill {

struct GnurbsBuildOptions {
  G2GnurbsOptions surface;  // how the surface is built (also inside the fit)
  GnurbsBrepOptions brep;   // how it becomes B-rep
  GnurbsFitOptions fit;     // with a target only; its `surface` is replaced by the one above
};

struct GnurbsBuildResult {
  QuadCage cage;                       // the cage the surface is over: as given, or as the fit moved it
  G2GnurbsResult surface;
  GnurbsBrep brep;
  GnurbsContinuity continuity;
  std::optional<GnurbsFitResult> fit;  // with a target: the fit's distances (its cage and surface moved to the ones above)
  double seconds = 0;                  // build (and fit) and B-rep, not the continuity measurement
  bool sound() const { return brep.valid && surface.warnings.empty(); }
  std::vector<std::string> warnings() const;  // the construction's, and the invalid shell's
  Outcome outcome() const;                    // Ok when sound, else Warned with the warnings
  std::string toJson() const;                 // gnurbsReportJson's, with "fit" after a fit, and the outcome's status
};

// `target`: null to build over the cage as it is; points to fit the cage to them first. Throws
// Error for an invalid cage (buildG2Gnurbs) or target (fitGnurbs).
GnurbsBuildResult buildGnurbs(const QuadCage& cage, const GnurbsBuildOptions& options = {}, const Eigen::MatrixX3d* target = nullptr);

}  // namespace holefill

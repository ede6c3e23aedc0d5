#include "gnurbs/gnurbs_build.h"

#include <chrono>

namespace holefill {

GnurbsBuildResult buildGnurbs(const QuadCage& cage, const GnurbsBuildOptions& o, const Eigen::MatrixX3d* target) {
  const auto t0 = std::chrono::steady_clock::now();
  GnurbsBuildResult r;
  if (target) {
    GnurbsFitOptions fo = o.fit;
    fo.surface = o.surface;
    GnurbsFitResult f = fitGnurbs(cage, *target, fo);
    r.cage = std::move(f.cage);  // the cage and surface are held once, here; `fit` keeps the distances
    r.surface = std::move(f.surface);
    r.fit = std::move(f);
  } else {
    r.cage = cage;
    r.surface = buildG2Gnurbs(cage, o.surface);
  }
  r.brep = gnurbsToBrep(r.surface, o.brep);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.continuity = measureGnurbsContinuity(r.surface);
  return r;
}

std::vector<std::string> GnurbsBuildResult::warnings() const {
  std::vector<std::string> w = surface.warnings;
  if (!brep.valid) w.push_back("the B-rep shell is invalid (BRepCheck): do not use it as it is");
  return w;
}

Outcome GnurbsBuildResult::outcome() const {
  Outcome o;
  o.warnings = warnings();
  o.status = sound() ? Status::Ok : Status::Warned;
  o.message = std::to_string(brep.faces) + " faces in " + (brep.closed ? "a closed" : "an open") + " shell, " +
              (brep.valid ? "valid" : "INVALID") + (surface.warnings.empty() ? "" : ", with warnings");
  return o;
}

std::string GnurbsBuildResult::toJson() const {
  const Outcome o = outcome();
  return gnurbsReportJson(surface, continuity, &brep, seconds, fit ? &*fit : nullptr, &o);
}

}  // namespace holefill

#include "fitting/tensor_fit.h"

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepLib.hxx>
#include <Geom2dAPI_Interpolate.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Precision.hxx>
#include <ShapeFix_Face.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt2d.hxx>
#include <TColgp_HArray1OfPnt2d.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Wire.hxx>
#include <Eigen/Sparse>
#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>
#include <utility>

#include "fill/fairness_energy.h"
#include "fitting/boundary_embedding.h"
#include "fitting/thb_spline.h"
#include "geometry/bspline_basis.h"
#include "geometry/error.h"
#include "geometry/polygon2d.h"
#include "geometry/spd_condition.h"
#include "geometry/surface_projection.h"
#include "mesh/mesh_holes.h"

namespace holefill {

namespace {

// A closed wire on the surface through the loop's parameters: one interpolating pcurve per
// stretch between corners (where the loop turns by more than 30° in uv), so corners stay sharp
// instead of being rounded (and overshot) by one periodic curve; periodic when there is none.
// `polyline`: the loop's own segments as pcurves (degree 1), simple wherever the loop is, for
// a noisy loop whose interpolants swing across each other.
TopoDS_Wire loopWire(const Handle(Geom_Surface)& surface, const std::vector<Eigen::Vector2d>& uv, bool polyline) {
  const int n = static_cast<int>(uv.size());
  std::vector<int> corners;
  for (int k = 0; k < n; ++k) {
    const Eigen::Vector2d a = uv[k] - uv[(k + n - 1) % n], b = uv[(k + 1) % n] - uv[k];
    if (a.norm() > 0 && b.norm() > 0 && std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0)) > M_PI / 6) corners.push_back(k);
  }
  auto curve = [&](const std::vector<Eigen::Vector2d>& pts, bool periodic) -> Handle(Geom2d_BSplineCurve) {
    if (polyline) {
      const int m = static_cast<int>(pts.size()) + (periodic ? 1 : 0);
      TColgp_Array1OfPnt2d poles(1, m);
      TColStd_Array1OfReal knots(1, m);
      TColStd_Array1OfInteger mults(1, m);
      for (int k = 0; k < m; ++k) {
        const Eigen::Vector2d& q = pts[static_cast<size_t>(k) % pts.size()];
        poles.SetValue(k + 1, gp_Pnt2d(q.x(), q.y()));
        knots.SetValue(k + 1, k);
        mults.SetValue(k + 1, k == 0 || k == m - 1 ? 2 : 1);
      }
      return new Geom2d_BSplineCurve(poles, knots, mults, 1);
    }
    Handle(TColgp_HArray1OfPnt2d) P = new TColgp_HArray1OfPnt2d(1, static_cast<int>(pts.size()));
    for (size_t k = 0; k < pts.size(); ++k) P->SetValue(static_cast<int>(k) + 1, gp_Pnt2d(pts[k].x(), pts[k].y()));
    Geom2dAPI_Interpolate interp(P, periodic ? Standard_True : Standard_False, 1e-12);
    interp.Perform();
    if (!interp.IsDone()) throw Error("could not build a trimming curve through the region's boundary");
    return interp.Curve();
  };
  BRepBuilderAPI_MakeWire wire;
  if (corners.empty()) {
    TopoDS_Edge e = BRepBuilderAPI_MakeEdge(curve(uv, true), surface);
    BRepLib::BuildCurves3d(e);
    wire.Add(e);
  } else {
    for (size_t c = 0; c < corners.size(); ++c) {
      const int from = corners[c], to = corners[(c + 1) % corners.size()];
      std::vector<Eigen::Vector2d> pts;
      for (int k = from;; k = (k + 1) % n) {
        pts.push_back(uv[k]);
        if (k == to && pts.size() > 1) break;
      }
      TopoDS_Edge e = BRepBuilderAPI_MakeEdge(curve(pts, false), surface);
      BRepLib::BuildCurves3d(e);
      wire.Add(e);
    }
  }
  if (!wire.IsDone()) throw Error("the trimming curves of the region's boundary do not close");
  return wire.Wire();
}

// The loop without its spikes: a vertex where the loop turns back on itself (by more than 170°)
// or repeats its predecessor. A map keeps sliver triangles folded at a held side where scan noise
// pushed a vertex past its neighbour (labeled_parameterization.h), and the loop then runs back
// and forth along that side: a wire BRepCheck calls self-intersecting. The vertices dropped stay
// fitted; the trimming curve passes within the noise of them.
std::vector<Eigen::Vector2d> withoutSpikes(std::vector<Eigen::Vector2d> loop) {
  const double cosLimit = std::cos(170 * M_PI / 180);
  for (bool dropped = true; dropped && loop.size() > 3;) {
    dropped = false;
    for (size_t k = 0; k < loop.size() && loop.size() > 3;) {
      const Eigen::Vector2d& p = loop[(k + loop.size() - 1) % loop.size()];
      const Eigen::Vector2d a = loop[k] - p, b = loop[(k + 1) % loop.size()] - loop[k];
      const double la = a.norm(), lb = b.norm();
      if (la == 0 || (lb > 0 && a.dot(b) < cosLimit * la * lb)) {
        loop.erase(loop.begin() + static_cast<std::ptrdiff_t>(k));
        dropped = true;
      } else {
        ++k;
      }
    }
  }
  return loop;
}

// The poles by least squares with the thin-plate term `fairness` (its matrix on the unknowns,
// built once: the knots stay while the parameters are corrected); the normal matrix and each
// unknown's support (the points in it) come back for the diagnostics. `thb`: the unknowns' map to
// the surface's (finest-level) B-splines (TensorFitOptions::refinedCells), null where the
// unknowns are the B-splines themselves.
struct PoleSolve {
  Eigen::MatrixX3d poles;
  Eigen::SparseMatrix<double> normal;
  int weak = 0;
};

PoleSolve solvePoles(const BSplineSurface& s, const Eigen::SparseMatrix<double>& fairness, const Eigen::SparseMatrix<double>* thb,
                     const Eigen::MatrixX3d& points, const Eigen::MatrixX2d& uv, Eigen::Index regionRows, const TensorFitOptions& o) {
  const int nv = s.numV(), n = s.numU() * nv;
  std::vector<Eigen::Triplet<double>> T;
  const double extra = std::sqrt(o.extraWeight);  // on the rows past the region's, of B and of the points alike
  Eigen::VectorXd rowWeight = Eigen::VectorXd::Ones(points.rows());
  rowWeight.tail(points.rows() - std::min(regionRows, points.rows())).setConstant(extra);
  for (Eigen::Index k = 0; k < points.rows(); ++k) {
    const int su = findSpan(s.knotsU, 3, uv(k, 0)), sv = findSpan(s.knotsV, 3, uv(k, 1));
    const Eigen::MatrixXd Bu = basisDerivatives(s.knotsU, 3, su, uv(k, 0), 0), Bv = basisDerivatives(s.knotsV, 3, sv, uv(k, 1), 0);
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) T.emplace_back(static_cast<int>(k), (su - 3 + a) * nv + (sv - 3 + b), Bu(0, a) * Bv(0, b));
  }
  Eigen::SparseMatrix<double> B(points.rows(), n);
  B.setFromTriplets(T.begin(), T.end());
  if (thb) B = B * *thb;
  // An unknown's support: the points whose basis row reaches it (a B-spline's whole span; a THB
  // function's truncated one).
  PoleSolve out;
  for (int c = 0; c < B.outerSize(); ++c) out.weak += B.outerIndexPtr()[c + 1] - B.outerIndexPtr()[c] < 3 ? 1 : 0;
  // The diagnostic is the data's own normal matrix, unweighted and without the thin plate, which
  // would hide a rank the points do not give (measured: a 40 × 32 fit of a 2,000-vertex U-slot
  // reported 10^7.5 with the thin plate in; its points alone left the matrix singular).
  out.normal = B.transpose() * B;
  const Eigen::SparseMatrix<double> weighted = rowWeight.asDiagonal() * B;
  Eigen::SparseMatrix<double> system = weighted.transpose() * weighted;
  const double scale = std::max(1e-300, system.diagonal().maxCoeff()) / std::max(1e-300, fairness.diagonal().maxCoeff());
  system += o.smoothing * scale * fairness;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(system);
  if (solver.info() != Eigen::Success) throw Error("the fitting system is singular: add smoothing or fewer control points");
  const Eigen::MatrixX3d coefficients = solver.solve(weighted.transpose() * (rowWeight.asDiagonal() * points));
  if (!coefficients.allFinite()) throw Error("the fit failed (non-finite control points)");
  out.poles = thb ? Eigen::MatrixX3d(*thb * coefficients) : coefficients;
  return out;
}

// Twice the signed area of region triangle t in the parameters.
double signedArea(const Eigen::MatrixX2d& uv, const Eigen::Vector3i& t) {
  const Eigen::Vector2d a = uv.row(t[1]) - uv.row(t[0]), b = uv.row(t[2]) - uv.row(t[0]);
  return a.x() * b.y() - a.y() * b.x();
}

}  // namespace

TensorFitResult fitTensorProduct(const Eigen::MatrixX3d& points, const Eigen::MatrixX2d& uv, const TriangleMesh& region,
                                 const Eigen::MatrixX2d& regionUV, const TensorFitOptions& o) {
  if (points.rows() != uv.rows() || region.vertices.rows() != regionUV.rows())
    throw Error("the fitted points and their parameters disagree in number");
  if (o.controlU < 4 || o.controlV < 4) throw Error("a cubic fit needs at least 4 control points in each direction");
  if (!(o.extraWeight > 0 && std::isfinite(o.extraWeight))) throw Error("the weight of the points past the region's must be positive");
  if (!points.allFinite() || !uv.allFinite() || !regionUV.allFinite()) throw Error("the fitting input has a non-finite value");
  const bool given = o.u1 > o.u0 && o.v1 > o.v0;
  double u0 = uv.col(0).minCoeff(), u1 = uv.col(0).maxCoeff(), v0 = uv.col(1).minCoeff(), v1 = uv.col(1).maxCoeff();
  if (!(u1 > u0 && v1 > v0)) throw Error("the points' parameters span no area");
  if (given) {
    if (!(o.u0 <= u0 && o.u1 >= u1 && o.v0 <= v0 && o.v1 >= v1)) throw Error("the fit's domain rectangle does not hold the points' parameters");
    u0 = o.u0, u1 = o.u1, v0 = o.v0, v1 = o.v1;
  }
  const Eigen::Index nr = region.vertices.rows();
  if (o.parameterCorrections > 0 && (points.rows() < nr || points.topRows(nr) != region.vertices || uv.topRows(nr) != regionUV))
    throw Error("parameter correction needs the region's vertices, at their parameters, first among the fitted points");

  TensorFitResult r;
  BSplineSurface& s = r.surface;
  s.degreeU = s.degreeV = 3;
  const auto knots = [](const std::vector<double>& interior, int control, double a, double b) {
    if (interior.empty()) return clampedUniformKnots(3, control - 3, a, b);
    for (size_t k = 0; k < interior.size(); ++k)
      if (!(interior[k] > 0 && interior[k] < 1 && (k == 0 || interior[k] > interior[k - 1])))
        throw Error("the interior knots must ascend strictly inside the domain (fractions in (0, 1))");
    std::vector<double> t(4, a);
    for (double f : interior) t.push_back(a + f * (b - a));
    t.insert(t.end(), 4, b);
    return t;
  };
  s.knotsU = knots(o.knotsU, o.controlU, u0, u1);
  s.knotsV = knots(o.knotsV, o.controlV, v0, v1);
  // Cells refined locally: the THB space over the uniform knots, the surface at its finest level.
  Eigen::SparseMatrix<double> thb;
  if (!o.refinedCells.empty()) {
    if (!o.knotsU.empty() || !o.knotsV.empty()) throw Error("cells are refined over uniform knots only (no interior knots given)");
    const ThbSpace space = refinedThbSpace(3, o.controlU - 3, o.controlV - 3, o.refinedCells);
    const int L = space.levels() - 1;
    s.knotsU = clampedUniformKnots(3, space.cellsU(L), u0, u1);
    s.knotsV = clampedUniformKnots(3, space.cellsV(L), v0, v1);
    thb = space.finestMap();
  }
  const Eigen::SparseMatrix<double>* map = thb.size() > 0 ? &thb : nullptr;
  const double diagonal = std::max(1e-300, (region.vertices.colwise().maxCoeff() - region.vertices.colwise().minCoeff()).norm());
  // Data error over the region's own vertices: {max, rms} / diagonal, and the vertex of the max.
  // At their parameters while the correction compares its rounds; `closest`: boundary vertices at
  // their parameters (where the face's edges run), inner ones at their closest points, for the
  // result. The correction keeps an inner vertex's parameters where its footpoint would turn a
  // triangle over, and its distance at them then is mostly along the surface: measured at
  // parameters, torus_crescent_n0p2 of the corpus reported 5.2 σ off the data where no vertex was
  // off by 4.8 σ along the normal and its fit was within 1.1 σ of the noise-free surface.
  const MeshHoleReport holes = findMeshHoles(region);
  if (holes.holes.empty()) throw Error("the region has no boundary to trim by");
  std::vector<char> onBoundary(static_cast<size_t>(nr), 0);
  for (const MeshHole& h : holes.holes)
    for (int v : h.loop) onBoundary[v] = 1;
  const auto dataError = [&](const BSplineSurface& f, const Eigen::MatrixX2d& ruv, bool closest) {
    double mx = 0, sum = 0;
    Eigen::Index at = 0;
    for (Eigen::Index k = 0; k < nr; ++k) {
      Eigen::Vector2d q = ruv.row(k).transpose();
      const Eigen::Vector3d p = region.vertices.row(k).transpose();
      const double d = (closest && !onBoundary[k] ? projectPointFrom(f, p, q) : (f.point(q.x(), q.y()) - p).norm()) / diagonal;
      if (d > mx) mx = d, at = k;
      sum += d * d;
    }
    return std::tuple<double, double, Eigen::Index>{mx, std::sqrt(sum / std::max<Eigen::Index>(1, nr)), at};
  };
  Eigen::MatrixX2d fitUV = uv;
  r.regionUV = regionUV;
  Eigen::SparseMatrix<double> fairness = fairnessMatrix(3, s.knotsU, 3, s.knotsV, FairnessWeights{1.0, 0.0});
  if (map) fairness = thb.transpose() * fairness * thb;
  r.unknowns = static_cast<int>(fairness.rows());
  PoleSolve solved = solvePoles(s, fairness, map, points, fitUV, nr, o);
  s.poles = solved.poles;
  std::tie(r.dataMax, r.dataRms, r.dataMaxAt) = dataError(s, r.regionUV, false);
  if (o.parameterCorrections > 0) {
    std::vector<double> sign0(region.triangles.rows());
    for (Eigen::Index t = 0; t < region.triangles.rows(); ++t) sign0[t] = signedArea(regionUV, region.triangles.row(t).transpose());
    ProjectionOptions po;
    for (int round = 0; round < o.parameterCorrections; ++round) {
      Eigen::MatrixX2d next = r.regionUV;
      for (Eigen::Index k = 0; k < nr; ++k) {
        Eigen::Vector2d q = next.row(k).transpose();
        projectPointFrom(s, region.vertices.row(k).transpose(), q, po);
        next.row(k) = q.transpose();
      }
      // A footpoint that would turn a triangle over (a sliver squeezed by the map, a vertex whose
      // closest point lies across a fold of the fit) keeps its last parameters, with the other
      // corners of that triangle; so do the ends of boundary edges that would cross another
      // (footpoints of a noisy boundary can zigzag past each other with every triangle upright,
      // and the face's wire then crosses itself); repeated, since a vertex held back can turn a
      // neighbour.
      bool turned = true;
      for (int pass = 0; pass < 20 && turned; ++pass) {
        turned = false;
        for (Eigen::Index t = 0; t < region.triangles.rows(); ++t) {
          if (sign0[t] == 0 || signedArea(next, region.triangles.row(t).transpose()) * sign0[t] > 0) continue;
          turned = true;
          for (int c = 0; c < 3; ++c) next.row(region.triangles(t, c)) = r.regionUV.row(region.triangles(t, c));
        }
        for (int v : boundaryCrossingVertices(holes, next)) {
          turned = true;
          next.row(v) = r.regionUV.row(v);
        }
      }
      if (turned) break;
      Eigen::MatrixX2d nextFit = fitUV;
      nextFit.topRows(nr) = next;
      BSplineSurface trial = s;
      PoleSolve again = solvePoles(trial, fairness, map, points, nextFit, nr, o);
      trial.poles = again.poles;
      const auto [mx, rms, at] = dataError(trial, next, false);
      if (!(rms < r.dataRms)) break;
      s = std::move(trial);
      solved = std::move(again);
      fitUV = std::move(nextFit);
      r.regionUV = std::move(next);
      r.dataMax = mx;
      r.dataRms = rms;
      r.dataMaxAt = at;
      ++r.correctionRounds;
    }
  }
  r.weakControlPoints = solved.weak;
  r.log10Condition = log10Condition(solved.normal);
  std::tie(r.dataMax, r.dataRms, r.dataMaxAt) = dataError(s, r.regionUV, true);

  // Trimmed face: the region's outer loop and its inner holes as pcurves.
  const Handle(Geom_BSplineSurface) g = toOcct(s);
  size_t outer = 0;
  for (size_t k = 1; k < holes.holes.size(); ++k)
    if (holes.holes[k].length > holes.holes[outer].length) outer = k;
  // The face's material lies left of its wires in the parameters: the outer loop anticlockwise,
  // the inner ones clockwise, whichever way the region's triangles ran (a region given clockwise
  // seen from its normal has its loops traced the other way, and its holes were refused as "Bad
  // orientation of sub-shape"). A loop that touches itself (the map folded at a held side, the
  // loop back along it: cone_blob_n0p2 of the corpus) has the fold cut off, at 1e-9 of the
  // domain's diagonal (well under any fitted feature, above rounding).
  const double touch = 1e-9 * std::hypot(s.knotsU.back() - s.knotsU.front(), s.knotsV.back() - s.knotsV.front());
  auto loopUV = [&](const MeshHole& h, bool outerLoop) {
    std::vector<Eigen::Vector2d> out;
    for (int v : h.loop) out.push_back(r.regionUV.row(v).transpose());
    if ((signedArea(out) > 0) != outerLoop) std::reverse(out.begin(), out.end());
    return withoutSelfContacts(withoutSpikes(out), touch);
  };
  // Smooth pcurves first; where they cross (a noisy loop's interpolants overshoot between close
  // stretches) the loop's own segments, which are simple when the loop is (the correction keeps it so).
  std::vector<std::vector<Eigen::Vector2d>> loops{loopUV(holes.holes[outer], true)};
  for (size_t k = 0; k < holes.holes.size(); ++k)
    if (k != outer) loops.push_back(loopUV(holes.holes[k], false));
  for (bool polyline : {false, true}) {
    BRepBuilderAPI_MakeFace mf(g, loopWire(g, loops[0], polyline));
    for (size_t k = 1; k < loops.size(); ++k) mf.Add(loopWire(g, loops[k], polyline));
    if (!mf.IsDone()) throw Error("could not trim the fitted surface by the region's boundary");
    ShapeFix_Face fix(mf.Face());
    fix.Perform();
    r.face = TopoDS::Face(fix.Face());
    // The 3D curves built from long pcurves on a wavy (noisy) fit stray from them past the
    // default tolerance, and BRepCheck refused the edges (InvalidSameParameterFlag); the edges'
    // tolerances are raised to what the curves really are instead.
    BRepLib::SameParameter(r.face, Precision::Confusion(), Standard_True);
    r.valid = BRepCheck_Analyzer(r.face).IsValid();
    if (r.valid) break;
  }
  return r;
}

}  // namespace holefill

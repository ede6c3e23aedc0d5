#include "fitting/tensor_fit.h"

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepLib.hxx>
#include <Geom2dAPI_Interpolate.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <ShapeFix_Face.hxx>
#include <TColgp_HArray1OfPnt2d.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Wire.hxx>
#include <Eigen/Sparse>
#include <algorithm>
#include <cmath>
#include <limits>

#include "fill/fairness_energy.h"
#include "geometry/bspline_basis.h"
#include "geometry/error.h"
#include "geometry/spd_condition.h"
#include "mesh/mesh_holes.h"

namespace holefill {

namespace {

// A closed wire on the surface through the loop's parameters: one interpolating pcurve per
// stretch between corners (where the loop turns by more than 30° in uv), so corners stay sharp
// instead of being rounded (and overshot) by one periodic curve; periodic when there is none.
TopoDS_Wire loopWire(const Handle(Geom_Surface)& surface, const std::vector<Eigen::Vector2d>& uv) {
  const int n = static_cast<int>(uv.size());
  std::vector<int> corners;
  for (int k = 0; k < n; ++k) {
    const Eigen::Vector2d a = uv[k] - uv[(k + n - 1) % n], b = uv[(k + 1) % n] - uv[k];
    if (a.norm() > 0 && b.norm() > 0 && std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0)) > M_PI / 6) corners.push_back(k);
  }
  auto curve = [&](const std::vector<Eigen::Vector2d>& pts, bool periodic) {
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

}  // namespace

TensorFitResult fitTensorProduct(const Eigen::MatrixX3d& points, const Eigen::MatrixX2d& uv, const TriangleMesh& region,
                                 const Eigen::MatrixX2d& regionUV, const TensorFitOptions& o) {
  if (points.rows() != uv.rows() || region.vertices.rows() != regionUV.rows())
    throw Error("the fitted points and their parameters disagree in number");
  if (o.controlU < 4 || o.controlV < 4) throw Error("a cubic fit needs at least 4 control points in each direction");
  if (!points.allFinite() || !uv.allFinite() || !regionUV.allFinite()) throw Error("the fitting input has a non-finite value");
  const double u0 = uv.col(0).minCoeff(), u1 = uv.col(0).maxCoeff(), v0 = uv.col(1).minCoeff(), v1 = uv.col(1).maxCoeff();
  if (!(u1 > u0 && v1 > v0)) throw Error("the points' parameters span no area");

  TensorFitResult r;
  BSplineSurface& s = r.surface;
  s.degreeU = s.degreeV = 3;
  s.knotsU = clampedUniformKnots(3, o.controlU - 3, u0, u1);
  s.knotsV = clampedUniformKnots(3, o.controlV - 3, v0, v1);
  const int n = o.controlU * o.controlV;
  std::vector<Eigen::Triplet<double>> T;
  std::vector<int> support(n, 0);
  for (Eigen::Index k = 0; k < points.rows(); ++k) {
    const int su = findSpan(s.knotsU, 3, uv(k, 0)), sv = findSpan(s.knotsV, 3, uv(k, 1));
    const Eigen::MatrixXd Bu = basisDerivatives(s.knotsU, 3, su, uv(k, 0), 0), Bv = basisDerivatives(s.knotsV, 3, sv, uv(k, 1), 0);
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) {
        const int pole = (su - 3 + a) * o.controlV + (sv - 3 + b);
        T.emplace_back(static_cast<int>(k), pole, Bu(0, a) * Bv(0, b));
        ++support[pole];
      }
  }
  for (int c : support) r.weakControlPoints += c < 3 ? 1 : 0;
  Eigen::SparseMatrix<double> B(points.rows(), n);
  B.setFromTriplets(T.begin(), T.end());
  Eigen::SparseMatrix<double> N = B.transpose() * B;
  const Eigen::SparseMatrix<double> E = fairnessMatrix(3, s.knotsU, 3, s.knotsV, FairnessWeights{1.0, 0.0});
  const double scale = std::max(1e-300, N.diagonal().maxCoeff()) / std::max(1e-300, Eigen::MatrixXd(E).diagonal().maxCoeff());
  N += o.smoothing * scale * E;
  r.log10Condition = log10Condition(N);
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(N);
  if (solver.info() != Eigen::Success) throw Error("the fitting system is singular: add smoothing or fewer control points");
  s.poles = solver.solve(B.transpose() * points);
  if (!s.poles.allFinite()) throw Error("the fit failed (non-finite control points)");

  // Data error over the region's own vertices.
  const double diagonal = std::max(1e-300, (region.vertices.colwise().maxCoeff() - region.vertices.colwise().minCoeff()).norm());
  double sum = 0;
  for (Eigen::Index k = 0; k < region.vertices.rows(); ++k) {
    const double d = (s.point(regionUV(k, 0), regionUV(k, 1)) - region.vertices.row(k).transpose()).norm() / diagonal;
    r.dataMax = std::max(r.dataMax, d);
    sum += d * d;
  }
  r.dataRms = std::sqrt(sum / std::max<Eigen::Index>(1, region.vertices.rows()));

  // Trimmed face: the region's outer loop and its inner holes as pcurves.
  const Handle(Geom_BSplineSurface) g = toOcct(s);
  const MeshHoleReport holes = findMeshHoles(region);
  if (holes.holes.empty()) throw Error("the region has no boundary to trim by");
  size_t outer = 0;
  for (size_t k = 1; k < holes.holes.size(); ++k)
    if (holes.holes[k].length > holes.holes[outer].length) outer = k;
  auto loopUV = [&](const MeshHole& h) {
    std::vector<Eigen::Vector2d> out;
    for (int v : h.loop) out.push_back(regionUV.row(v).transpose());
    return out;
  };
  BRepBuilderAPI_MakeFace mf(g, loopWire(g, loopUV(holes.holes[outer])));
  for (size_t k = 0; k < holes.holes.size(); ++k)
    if (k != outer) mf.Add(loopWire(g, loopUV(holes.holes[k])));
  if (!mf.IsDone()) throw Error("could not trim the fitted surface by the region's boundary");
  ShapeFix_Face fix(mf.Face());
  fix.Perform();
  r.face = TopoDS::Face(fix.Face());
  r.valid = BRepCheck_Analyzer(r.face).IsValid();
  return r;
}

}  // namespace holefill

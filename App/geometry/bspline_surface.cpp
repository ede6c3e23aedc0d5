#include "geometry/bspline_surface.h"

#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>

#include "geometry/bspline_basis.h"
#include "geometry/error.h"

namespace holefill {

std::array<std::array<Eigen::Vector3d, 4>, 4> BSplineSurface::derivatives(double u, double v, int order) const {
  HF_CHECK(order >= 0 && order <= 3, "surface derivatives are available up to order 3");
  std::array<std::array<Eigen::Vector3d, 4>, 4> d;
  for (auto& row : d) row.fill(Eigen::Vector3d::Zero());
  const int su = findSpan(knotsU, degreeU, u), sv = findSpan(knotsV, degreeV, v);
  const Eigen::MatrixXd Nu = basisDerivatives(knotsU, degreeU, su, u, std::min(order, degreeU));
  const Eigen::MatrixXd Nv = basisDerivatives(knotsV, degreeV, sv, v, std::min(order, degreeV));
  for (int k = 0; k <= std::min(order, degreeU); ++k)
    for (int l = 0; k + l <= order && l <= degreeV; ++l) {
      Eigen::Vector3d acc = Eigen::Vector3d::Zero();
      for (int a = 0; a <= degreeU; ++a) {
        Eigen::Vector3d row = Eigen::Vector3d::Zero();
        for (int b = 0; b <= degreeV; ++b)
          row += Nv(l, b) * poles.row(index(su - degreeU + a, sv - degreeV + b)).transpose();
        acc += Nu(k, a) * row;
      }
      d[k][l] = acc;
    }
  return d;
}

Eigen::Vector3d BSplineSurface::point(double u, double v) const { return derivatives(u, v, 0)[0][0]; }

namespace {
// Boehm insertion of one knot into a curve of control points (The NURBS Book A5.1, r = 1).
std::vector<Eigen::Vector3d> insertIntoCurve(const std::vector<double>& U, int p, const std::vector<Eigen::Vector3d>& P,
                                             double knot, int span) {
  const int n = static_cast<int>(P.size());
  std::vector<Eigen::Vector3d> Q(n + 1);
  for (int i = 0; i <= span - p; ++i) Q[i] = P[i];
  for (int i = span; i < n; ++i) Q[i + 1] = P[i];
  for (int i = span - p + 1; i <= span; ++i) {
    const double a = (knot - U[i]) / (U[i + p] - U[i]);
    Q[i] = a * P[i] + (1.0 - a) * P[i - 1];
  }
  return Q;
}
}  // namespace

BSplineSurface insertKnot(const BSplineSurface& s, int dir, double knot) {
  const std::vector<double>& U = dir == 0 ? s.knotsU : s.knotsV;
  const int p = dir == 0 ? s.degreeU : s.degreeV;
  HF_CHECK(knot > U.front() && knot < U.back(), "knot to insert must lie inside the domain");
  const int span = findSpan(U, p, knot);
  BSplineSurface r = s;
  std::vector<double>& R = dir == 0 ? r.knotsU : r.knotsV;
  R.insert(R.begin() + span + 1, knot);
  const int nu = s.numU(), nv = s.numV();
  r.poles.resize(static_cast<Eigen::Index>(r.numU()) * r.numV(), 3);
  if (dir == 0) {
    for (int j = 0; j < nv; ++j) {
      std::vector<Eigen::Vector3d> col(nu);
      for (int i = 0; i < nu; ++i) col[i] = s.poles.row(s.index(i, j));
      const auto q = insertIntoCurve(U, p, col, knot, span);
      for (int i = 0; i <= nu; ++i) r.poles.row(r.index(i, j)) = q[i];
    }
  } else {
    for (int i = 0; i < nu; ++i) {
      std::vector<Eigen::Vector3d> row(nv);
      for (int j = 0; j < nv; ++j) row[j] = s.poles.row(s.index(i, j));
      const auto q = insertIntoCurve(U, p, row, knot, span);
      for (int j = 0; j <= nv; ++j) r.poles.row(r.index(i, j)) = q[j];
    }
  }
  return r;
}

namespace {
void splitKnots(const std::vector<double>& U, TColStd_Array1OfReal*& knots, TColStd_Array1OfInteger*& mults) {
  std::vector<double> k;
  std::vector<int> m;
  for (double u : U) {
    if (!k.empty() && u == k.back()) ++m.back();
    else { k.push_back(u); m.push_back(1); }
  }
  knots = new TColStd_Array1OfReal(1, static_cast<int>(k.size()));
  mults = new TColStd_Array1OfInteger(1, static_cast<int>(k.size()));
  for (size_t i = 0; i < k.size(); ++i) {
    knots->SetValue(static_cast<int>(i) + 1, k[i]);
    mults->SetValue(static_cast<int>(i) + 1, m[i]);
  }
}
}  // namespace

Handle(Geom_BSplineSurface) toOcct(const BSplineSurface& s) {
  TColgp_Array2OfPnt P(1, s.numU(), 1, s.numV());
  for (int i = 0; i < s.numU(); ++i)
    for (int j = 0; j < s.numV(); ++j) {
      const auto r = s.poles.row(s.index(i, j));
      P.SetValue(i + 1, j + 1, gp_Pnt(r(0), r(1), r(2)));
    }
  TColStd_Array1OfReal *ku, *kv;
  TColStd_Array1OfInteger *mu, *mv;
  splitKnots(s.knotsU, ku, mu);
  splitKnots(s.knotsV, kv, mv);
  Handle(Geom_BSplineSurface) g = new Geom_BSplineSurface(P, *ku, *kv, *mu, *mv, s.degreeU, s.degreeV);
  delete ku; delete kv; delete mu; delete mv;
  return g;
}

BSplineSurface fromOcct(const Handle(Geom_BSplineSurface)& g) {
  HF_CHECK(!g.IsNull(), "null B-spline surface");
  HF_CHECK(!g->IsURational() && !g->IsVRational(), "rational B-spline surfaces are not supported here");
  HF_CHECK(!g->IsUPeriodic() && !g->IsVPeriodic(), "periodic B-spline surfaces are not supported here");
  BSplineSurface s;
  s.degreeU = g->UDegree();
  s.degreeV = g->VDegree();
  for (int i = 1; i <= g->NbUKnots(); ++i)
    for (int m = 0; m < g->UMultiplicity(i); ++m) s.knotsU.push_back(g->UKnot(i));
  for (int i = 1; i <= g->NbVKnots(); ++i)
    for (int m = 0; m < g->VMultiplicity(i); ++m) s.knotsV.push_back(g->VKnot(i));
  s.poles.resize(static_cast<Eigen::Index>(g->NbUPoles()) * g->NbVPoles(), 3);
  for (int i = 0; i < g->NbUPoles(); ++i)
    for (int j = 0; j < g->NbVPoles(); ++j) {
      const gp_Pnt p = g->Pole(i + 1, j + 1);
      s.poles.row(s.index(i, j)) << p.X(), p.Y(), p.Z();
    }
  return s;
}

}  // namespace holefill

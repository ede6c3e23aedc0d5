#include "fill/parameterizer.h"

#include <BRepAdaptor_Curve2d.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRep_Tool.hxx>
#include <Geom_BSplineSurface.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <cmath>

#include "geometry/bspline_surface.h"
#include "geometry/error.h"
#include "geometry/polygon2d.h"
#include "learn/uvtran.h"

namespace holefill {

ParamMethod paramMethodFromString(const std::string& s) {
  if (s == "np" || s == "NP" || s == "plane") return ParamMethod::NearestPlane;
  if (s == "mvc" || s == "MVC" || s == "polygon") return ParamMethod::MeanValue;
  if (s == "auto") return ParamMethod::Auto;
  if (s == "support" || s == "exact") return ParamMethod::Support;
  if (s == "uvtran" || s == "UVTran") return ParamMethod::Uvtran;
  throw Error("unknown parameterization method '" + s + "': use np, mvc, auto, uvtran or support");
}

std::string toString(ParamMethod m) {
  switch (m) {
    case ParamMethod::NearestPlane: return "np";
    case ParamMethod::MeanValue: return "mvc";
    case ParamMethod::Auto: return "auto";
    case ParamMethod::Support: return "support";
    case ParamMethod::Uvtran: return "uvtran";
  }
  return "?";
}

namespace {

// Least-squares plane of the loop (arc-length weighted): centre, and the principal axes by
// increasing variance (axis(0) is the normal, axis(2) the longest in-plane direction).
struct PlaneFit {
  Eigen::Vector3d centre;
  Eigen::Vector3d variance;
  Eigen::Matrix3d axis;
};

PlaneFit fitPlane(const std::vector<BoundarySample>& s) {
  PlaneFit f;
  f.centre.setZero();
  double W = 0;
  for (const auto& x : s) { f.centre += x.weight * x.point; W += x.weight; }
  f.centre /= W;
  Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
  for (const auto& x : s) C += x.weight * (x.point - f.centre) * (x.point - f.centre).transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(C);
  f.variance = es.eigenvalues();
  f.axis = es.eigenvectors();
  return f;
}

void nearestPlane(const std::vector<BoundarySample>& s, Parameterization& P) {
  const PlaneFit f = fitPlane(s);
  for (const auto& x : s) P.uv.emplace_back((x.point - f.centre).dot(f.axis.col(2)), (x.point - f.centre).dot(f.axis.col(1)));
}

// The pcurve as a polygon of at most ~256 vertices (containment and mean value coordinates are
// linear in its size); `at` holds each vertex's sample index.
Polygon2 pcurvePolygon(const std::vector<Eigen::Vector2d>& uv, std::vector<int>& at) {
  Polygon2 poly;
  const int stride = std::max<int>(1, static_cast<int>(uv.size()) / 256);
  for (int i = 0; i < static_cast<int>(uv.size()); i += stride) { poly.push_back(uv[i]); at.push_back(i); }
  return poly;
}

// Interior nodes of a grid of `cells` x `cells` over [lo, hi] that lie inside the polygon.
std::vector<Eigen::Vector2d> gridInside(const Polygon2& poly, const Eigen::Vector2d& lo, const Eigen::Vector2d& hi,
                                        int cells) {
  std::vector<Eigen::Vector2d> out;
  for (int i = 1; i < cells; ++i)
    for (int j = 1; j < cells; ++j) {
      const Eigen::Vector2d x = lo + Eigen::Vector2d((hi - lo).x() * i / cells, (hi - lo).y() * j / cells);
      if (contains(poly, x)) out.push_back(x);
    }
  return out;
}

// The grid points of the pcurve's bounding box that lie inside it.
std::vector<Eigen::Vector2d> gridInsidePcurve(const Polygon2& poly, const std::vector<Eigen::Vector2d>& uv, int cells) {
  Eigen::AlignedBox2d box;
  for (const auto& q : uv) box.extend(q);
  return gridInside(poly, box.min(), box.max(), cells);
}

void meanValue(const Hole& hole, const std::vector<BoundarySample>& s, const ParameterizationOptions& opt,
               Parameterization& P) {
  const int n = static_cast<int>(s.size());
  // Corner samples: the first sample of each edge that starts with a corner.
  std::vector<int> corners;
  for (int i = 0; i < n; ++i)
    if ((i == 0 || s[i].edge != s[i - 1].edge) && hole.edges[s[i].edge].cornerAtStart) corners.push_back(i);
  double L = 0;
  for (int i = 0; i < n; ++i) L += (s[(i + 1) % n].point - s[i].point).norm();
  P.uv.assign(n, Eigen::Vector2d::Zero());
  if (static_cast<int>(corners.size()) < opt.minCorners) {
    // A smooth loop (or one with one or two corners) has no polygon to map to: it goes onto a
    // circle by arc length, the N-gon's limit, so no corner appears in the pcurve that the
    // boundary does not have.
    P.warnings.push_back("the loop has " + std::to_string(corners.size()) + " corners; MVC maps it onto a circle");
    const double R = L / (2.0 * M_PI);
    const int first = corners.empty() ? 0 : corners[0];
    double acc = 0;
    for (int k = 0; k < n; ++k) {
      const int i = (first + k) % n;
      if (k > 0) acc += (s[i].point - s[(i + n - 1) % n].point).norm();
      P.uv[i] = R * Eigen::Vector2d(std::cos(2 * M_PI * acc / L), std::sin(2 * M_PI * acc / L));
    }
  } else {
    const int N = static_cast<int>(corners.size());
    // Arc lengths along each side, from corner c to corner c + 1.
    std::vector<std::vector<double>> arc(N);
    for (int c = 0; c < N; ++c) {
      const int a = corners[c], b = corners[(c + 1) % N];
      const int len = (b - a + n) % n == 0 ? n : (b - a + n) % n;
      arc[c].assign(len + 1, 0.0);
      for (int k = 1; k <= len; ++k) arc[c][k] = arc[c][k - 1] + (s[(a + k) % n].point - s[(a + k - 1) % n].point).norm();
    }
    std::vector<Eigen::Vector2d> V(N);
    if (N == 4) {
      // A four-sided loop goes onto the axis-aligned rectangle whose width and height are the
      // mean lengths of its opposite sides: its sides are iso-lines of the tensor-product fill
      // (refining a side's spans refines along that side only, no domain corner lies outside the
      // hole), and a long thin strip keeps its proportions, so the knots are spent along it, not
      // across (a square made a 15:1 strip of the hammer model run out of poles).
      const double w = 0.5 * (arc[0].back() + arc[2].back()), h = 0.5 * (arc[1].back() + arc[3].back());
      V = {Eigen::Vector2d(-w / 2, -h / 2), Eigen::Vector2d(w / 2, -h / 2), Eigen::Vector2d(w / 2, h / 2),
           Eigen::Vector2d(-w / 2, h / 2)};
    } else {
      // The regular N-gon with the loop's perimeter, its first side along u.
      const double R = L / (2.0 * N * std::sin(M_PI / N));
      const double start = -M_PI / 2 - M_PI / N;
      for (int c = 0; c < N; ++c) V[c] = R * Eigen::Vector2d(std::cos(start + 2 * M_PI * c / N), std::sin(start + 2 * M_PI * c / N));
    }
    for (int c = 0; c < N; ++c) {
      const int a = corners[c];
      const std::vector<double>& acc = arc[c];
      const int len = static_cast<int>(acc.size()) - 1;
      for (int k = 0; k < len; ++k) {
        const double f = acc[len] > 0 ? acc[k] / acc[len] : double(k) / len;
        P.uv[(a + k) % n] = (1 - f) * V[c] + f * V[(c + 1) % N];
      }
    }
  }
  P.cornerSamples = corners;
  // Interior reference points by mean value interpolation of the boundary.
  std::vector<int> at;
  const Polygon2 poly = pcurvePolygon(P.uv, at);
  for (const auto& x : gridInsidePcurve(poly, P.uv, opt.interiorReferenceGrid)) {
    const Eigen::VectorXd w = meanValueCoordinates(poly, x);
    Eigen::Vector3d p = Eigen::Vector3d::Zero();
    for (int k = 0; k < w.size(); ++k) p += w(k) * s[at[k]].point;
    P.interiorUV.push_back(x);
    P.interiorXYZ.push_back(p);
  }
}

// UVTran's interior reference points: its projection surface inside the pcurve.
void interiorReferences(const BSplineSurface& surf, const ParameterizationOptions& opt, Parameterization& P) {
  std::vector<int> at;
  const Polygon2 poly = pcurvePolygon(P.uv, at);
  for (const auto& x : gridInsidePcurve(poly, P.uv, opt.interiorReferenceGrid)) {
    P.interiorUV.push_back(x);
    P.interiorXYZ.push_back(surf.point(x.x(), x.y()));
  }
}

void uvtran(const std::vector<BoundarySample>& s, const ParameterizationOptions& opt, Parameterization& P) {
  std::vector<Eigen::Vector3d> loop;
  for (const auto& x : s) loop.push_back(x.point);
  learn::UvtranOptions uo;
  uo.weights = opt.uvtranWeights;
  const learn::UvtranPrediction pred = learn::predictUvtran(loop, uo);
  Eigen::AlignedBox3d box;
  for (const auto& p : loop) box.extend(p);
  if (pred.maxDistance > opt.uvtranMaxDistance * box.diagonal().norm())
    throw Error("the predicted projection surface lies " + std::to_string(pred.maxDistance / box.diagonal().norm()) +
                " boundary diagonals from the boundary");
  P.uv = pred.uv;
  P.projectionSurface = pred.surface;
  interiorReferences(pred.surface, opt, P);
}

void support(const Hole& hole, const std::vector<BoundarySample>& s, Parameterization& P) {
  const TopoDS_Face& f = hole.edges[0].support;
  for (const auto& e : hole.edges)
    if (!e.support.IsSame(f))
      throw Error("the 'support' parameterization needs a hole cut out of a single face; use np or mvc");
  for (const auto& x : s) {
    BRepAdaptor_Curve2d pc(hole.edges[x.edge].edge, f);
    const gp_Pnt2d uv = pc.Value(x.t);
    P.uv.emplace_back(uv.X(), uv.Y());
  }
  BRepAdaptor_Surface as(f, Standard_False);
  P.u0 = as.FirstUParameter(); P.u1 = as.LastUParameter();
  P.v0 = as.FirstVParameter(); P.v1 = as.LastVParameter();
  Handle(Geom_Surface) g = BRep_Tool::Surface(f);
  Handle(Geom_BSplineSurface) b = Handle(Geom_BSplineSurface)::DownCast(g);
  if (!b.IsNull() && !b->IsURational() && !b->IsVRational() && !b->IsUPeriodic() && !b->IsVPeriodic()) {
    const BSplineSurface bs = fromOcct(b);
    if (bs.degreeU == 3 && bs.degreeV == 3) { P.knotsU = bs.knotsU; P.knotsV = bs.knotsV; }
  }
  if (!std::isfinite(P.u0) || !std::isfinite(P.u1) || !std::isfinite(P.v0) || !std::isfinite(P.v1)) {
    P.u0 = P.v0 = 1e300; P.u1 = P.v1 = -1e300;  // unbounded surface: recomputed from the pcurve below
  }
}

// Common to all methods: reject folds and zero area, orient counter-clockwise, set the domain.
void finish(Parameterization& P, ParamMethod method, bool fixedDomain, const ParameterizationOptions& opt) {
  Polygon2 poly(P.uv.begin(), P.uv.end());
  const double area = signedArea(poly);
  Eigen::AlignedBox2d box;
  for (const auto& q : P.uv) box.extend(q);
  if (selfIntersects(poly))
    throw Error("the " + toString(method) + " parameterization folds the hole boundary (self-intersecting pcurve); "
                "try another method");
  if (!(std::abs(area) > 1e-12 * box.diagonal().squaredNorm()))
    throw Error("the " + toString(method) + " parameterization maps the hole boundary onto a curve without area: "
                "the loop is degenerate for this method");
  if (area < 0) {  // mirror u about the domain centre: keeps the domain, reverses orientation
    P.mirroredU = true;
    const double c = fixedDomain ? P.u0 + P.u1 : box.min().x() + box.max().x();
    for (auto& q : P.uv) q.x() = c - q.x();
    for (auto& q : P.interiorUV) q.x() = c - q.x();
    if (!P.knotsU.empty()) {
      std::vector<double> k;
      for (auto it = P.knotsU.rbegin(); it != P.knotsU.rend(); ++it) k.push_back(c - *it);
      P.knotsU = k;
    }
    box = Eigen::AlignedBox2d();
    for (const auto& q : P.uv) box.extend(q);
  }
  if (!fixedDomain) {
    const Eigen::Vector2d ext = box.sizes();
    const double m = opt.margin * std::max(ext.x(), ext.y());
    P.u0 = box.min().x() - m; P.u1 = box.max().x() + m;
    P.v0 = box.min().y() - m; P.v1 = box.max().y() + m;
  }
}

}  // namespace

Parameterization parameterize(const Hole& hole, const std::vector<BoundarySample>& samples, ParamMethod method,
                              const ParameterizationOptions& opt) {
  HF_CHECK(samples.size() >= 6, "a hole boundary needs at least 6 samples");
  const PlaneFit plane = fitPlane(samples);
  // A loop whose points lie on a line (a slit, two coincident edges) encloses nothing.
  if (!(plane.variance(1) > 1e-12 * plane.variance(2)))
    throw Error("the hole boundary is degenerate: its points lie on a line, so it encloses no area");
  if (method == ParamMethod::Auto) {
    // NP suits holes whose support normals all stay within 36.9 degrees of the plane's normal (the
    // fill is a height field over the plane); steeper boundaries get compressed there, so MVC.
    const Eigen::Vector3d m = plane.axis.col(0);
    double minCos = 1.0, offPlane = 0, extent = 0;
    for (const auto& x : samples) {
      if (x.normalValid) minCos = std::min(minCos, std::abs(x.normal.dot(m)));
      offPlane = std::max(offPlane, std::abs((x.point - plane.centre).dot(m)));
      extent = std::max(extent, (x.point - plane.centre).norm());
    }
    const std::string steep = std::to_string(std::acos(minCos) * 180.0 / M_PI);
    if (minCos >= opt.autoPlaneCos) {
      try {
        Parameterization np = parameterize(hole, samples, ParamMethod::NearestPlane, opt);
        np.warnings.push_back("auto: np (support normals within " + steep + " deg of the plane's)");
        return np;
      } catch (const Error&) {
        // A planar loop projects exactly: its fold is the loop's own self-intersection, which
        // MVC would only hide. A curled spatial loop may fold in projection and still be fine.
        if (offPlane <= 1e-9 * extent) throw;
      }
    }
    Parameterization mvc = parameterize(hole, samples, ParamMethod::MeanValue, opt);
    mvc.warnings.push_back("auto: mvc (support normals up to " + steep + " deg from the plane's)");
    return mvc;
  }
  if (method == ParamMethod::Uvtran) {
    try {
      Parameterization P;
      P.chosen = method;
      uvtran(samples, opt, P);
      finish(P, method, false, opt);
      return P;
    } catch (const Error& e) {
      Parameterization m = parameterize(hole, samples, ParamMethod::MeanValue, opt);
      m.warnings.insert(m.warnings.begin(), std::string("uvtran failed, fell back to mvc: ") + e.what());
      return m;
    }
  }
  Parameterization P;
  P.chosen = method;
  bool fixedDomain = false;
  switch (method) {
    case ParamMethod::NearestPlane: nearestPlane(samples, P); break;
    case ParamMethod::MeanValue: meanValue(hole, samples, opt, P); break;
    case ParamMethod::Support: support(hole, samples, P); fixedDomain = P.u0 < P.u1; break;
    case ParamMethod::Auto: case ParamMethod::Uvtran: break;  // handled above
  }
  finish(P, method, fixedDomain, opt);
  return P;
}

}  // namespace holefill

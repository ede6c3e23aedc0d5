#include "geometry/surface_projection.h"

#include <algorithm>
#include <cmath>

namespace holefill {

namespace {

struct Domain {
  double u0, u1, v0, v1;
  Eigen::Vector2d clamp(const Eigen::Vector2d& q) const {
    return {std::clamp(q.x(), u0, u1), std::clamp(q.y(), v0, v1)};
  }
};

// Newton on f(u,v) = |S - p|^2 / 2 with a step halving line search; returns the distance reached.
double newton(const BSplineSurface& s, const Domain& D, const Eigen::Vector3d& p, Eigen::Vector2d& uv,
              const ProjectionOptions& opt) {
  double f = (s.point(uv.x(), uv.y()) - p).squaredNorm();
  for (int it = 0; it < opt.maxIterations; ++it) {
    const auto d = s.derivatives(uv.x(), uv.y(), 2);
    const Eigen::Vector3d r = d[0][0] - p;
    Eigen::Vector2d g(d[1][0].dot(r), d[0][1].dot(r));
    Eigen::Matrix2d H;
    H(0, 0) = d[1][0].squaredNorm() + d[2][0].dot(r);
    H(0, 1) = H(1, 0) = d[1][0].dot(d[0][1]) + d[1][1].dot(r);
    H(1, 1) = d[0][1].squaredNorm() + d[0][2].dot(r);
    Eigen::Vector2d step;
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(H);
    if (es.eigenvalues().minCoeff() > 1e-12 * std::max(1.0, es.eigenvalues().maxCoeff())) {
      step = -H.ldlt().solve(g);
    } else {  // saddle or flat direction: Gauss-Newton (first fundamental form only)
      Eigen::Matrix2d Gn;
      Gn << d[1][0].squaredNorm(), d[1][0].dot(d[0][1]), d[1][0].dot(d[0][1]), d[0][1].squaredNorm();
      step = -(Gn + 1e-12 * Eigen::Matrix2d::Identity()).ldlt().solve(g);
    }
    double t = 1.0;
    bool moved = false;
    for (int k = 0; k < 12; ++k, t *= 0.5) {
      const Eigen::Vector2d q = D.clamp(uv + t * step);
      const double fq = (s.point(q.x(), q.y()) - p).squaredNorm();
      if (fq <= f) {
        moved = (q - uv).squaredNorm() > opt.tolerance;
        uv = q;
        f = fq;
        break;
      }
    }
    if (!moved) break;
  }
  return std::sqrt(f);
}

}  // namespace

ProjectionResult projectSequence(const BSplineSurface& s, const std::vector<Eigen::Vector3d>& points,
                                 const ProjectionOptions& opt) {
  const Domain S{s.knotsU[s.degreeU], s.knotsU[s.knotsU.size() - s.degreeU - 1], s.knotsV[s.degreeV],
                 s.knotsV[s.knotsV.size() - s.degreeV - 1]};
  const double eu = opt.extension * (S.u1 - S.u0), ev = opt.extension * (S.v1 - S.v0);
  const Domain D{S.u0 - eu, S.u1 + eu, S.v0 - ev, S.v1 + ev};
  const int G = opt.gridCells;
  std::vector<Eigen::Vector2d> gridUV;
  std::vector<Eigen::Vector3d> gridXYZ;
  for (int i = 0; i <= G; ++i)
    for (int j = 0; j <= G; ++j) {
      const Eigen::Vector2d q(S.u0 + (S.u1 - S.u0) * i / G, S.v0 + (S.v1 - S.v0) * j / G);
      gridUV.push_back(q);
      gridXYZ.push_back(s.point(q.x(), q.y()));
    }
  auto gridSeed = [&](const Eigen::Vector3d& p) {
    size_t best = 0;
    for (size_t k = 1; k < gridXYZ.size(); ++k)
      if ((gridXYZ[k] - p).squaredNorm() < (gridXYZ[best] - p).squaredNorm()) best = k;
    return gridUV[best];
  };
  Eigen::AlignedBox3d box;
  for (const auto& p : points) box.extend(p);
  const double same = 1e-9 * box.diagonal().norm();
  ProjectionResult r;
  Eigen::Vector2d prev;
  double prevDist = 0;
  for (size_t k = 0; k < points.size(); ++k) {
    const Eigen::Vector3d& p = points[k];
    Eigen::Vector2d uv;
    double dist;
    if (k == 0) {
      uv = gridSeed(p);
      ++r.gridSearches;
      dist = newton(s, D, p, uv, opt);
    } else if ((p - points[k - 1]).norm() <= same || (p - points[0]).norm() <= same) {
      // A repeated point (a corner sampled by both of its edges, a loop closed on its start)
      // gets the very same parameters: two Newton answers a convergence tolerance apart would
      // put a tiny segment of random direction into the pcurve, which can cross its neighbours.
      const bool first = (p - points[0]).norm() <= same;
      uv = first ? r.uv[0] : prev;
      dist = first ? r.distance[0] : prevDist;
    } else {
      uv = prev;
      dist = newton(s, D, p, uv, opt);
      // A jump in distance means Newton stopped on a far local minimum: reseed from the grid.
      const double step = (p - points[k - 1]).norm();
      if (dist > prevDist + 2 * step + 1e-9) {
        Eigen::Vector2d alt = gridSeed(p);
        ++r.gridSearches;
        const double d2 = newton(s, D, p, alt, opt);
        if (d2 < dist) { uv = alt; dist = d2; }
      }
    }
    r.uv.push_back(uv);
    r.distance.push_back(dist);
    prev = uv;
    prevDist = dist;
  }
  return r;
}

double projectPointFrom(const BSplineSurface& s, const Eigen::Vector3d& point, Eigen::Vector2d& uv, const ProjectionOptions& opt) {
  const Domain D{s.knotsU[s.degreeU], s.knotsU[s.knotsU.size() - s.degreeU - 1], s.knotsV[s.degreeV],
                 s.knotsV[s.knotsV.size() - s.degreeV - 1]};
  uv = D.clamp(uv);
  return newton(s, D, point, uv, opt);
}

}  // namespace holefill

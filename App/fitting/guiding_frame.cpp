#include "fitting/guiding_frame.h"

#include <algorithm>
#include <cmath>

#include "geometry/bspline_basis.h"
#include "geometry/error.h"

namespace holefill {

namespace {

std::vector<double> bezierKnots(int n) {
  std::vector<double> k(2 * (n + 1), 0.0);
  std::fill(k.begin() + n + 1, k.end(), 1.0);
  return k;
}

// Row d: the d-th derivatives of the n + 1 Bernstein polynomials of degree n at t.
Eigen::MatrixXd bernstein(int n, double t, int d) { return basisDerivatives(bezierKnots(n), n, n, std::clamp(t, 0.0, 1.0), d); }

// ∫₀¹ B_i''(t) B_j''(t) dt (Gauss–Legendre, exact for the degrees used).
Eigen::MatrixXd bendingMatrix(int n) {
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n + 1, n + 1);
  if (n < 2) return K;
  std::vector<double> x, w;
  gaussLegendre(8, x, w);
  for (size_t q = 0; q < x.size(); ++q) {
    const Eigen::VectorXd b2 = bernstein(n, 0.5 * (x[q] + 1), 2).row(2).transpose();
    K += 0.5 * w[q] * b2 * b2.transpose();
  }
  return K;
}

Eigen::Vector3d curvePoint(const Eigen::MatrixX3d& P, double t, int d = 0) {
  const int n = static_cast<int>(P.rows()) - 1;
  if (d > n) return Eigen::Vector3d::Zero();
  return (bernstein(n, t, d).row(d) * P).transpose();
}

// Closest parameter to q on the curve, by Newton from t (and the ends, whichever is nearest).
double project(const Eigen::MatrixX3d& P, const Eigen::Vector3d& q, double t) {
  for (int it = 0; it < 30; ++it) {
    const Eigen::Vector3d c = curvePoint(P, t), d1 = curvePoint(P, t, 1), d2 = curvePoint(P, t, 2);
    const double f = (c - q).dot(d1), df = d1.squaredNorm() + (c - q).dot(d2);
    if (!(df > 0)) break;
    const double next = std::clamp(t - f / df, 0.0, 1.0);
    if (std::abs(next - t) < 1e-14) break;
    t = next;
  }
  for (double end : {0.0, 1.0})
    if ((curvePoint(P, end) - q).squaredNorm() < (curvePoint(P, t) - q).squaredNorm()) t = end;
  return t;
}

// A Bézier curve's point at any t, also outside [0, 1] (de Casteljau extrapolates).
Eigen::Vector3d casteljau(Eigen::MatrixX3d P, double t) {
  for (Eigen::Index r = P.rows() - 1; r > 0; --r)
    for (Eigen::Index k = 0; k < r; ++k) P.row(k) = (1 - t) * P.row(k) + t * P.row(k + 1);
  return P.row(0).transpose();
}

// Least-squares Bézier of degree ≤ 3 through the points, parameters from chord length and then
// corrected by projection (so that points on a cubic give that cubic, and its continuation).
Eigen::MatrixX3d ownCurve(const std::vector<Eigen::Vector3d>& pts) {
  const int n = std::min<int>(3, static_cast<int>(pts.size()) - 1);
  std::vector<double> t(pts.size(), 0.0);
  for (size_t k = 1; k < pts.size(); ++k) t[k] = t[k - 1] + (pts[k] - pts[k - 1]).norm();
  for (double& x : t) x = t.back() > 0 ? x / t.back() : 0.0;
  Eigen::MatrixX3d Y(pts.size(), 3), P;
  for (size_t k = 0; k < pts.size(); ++k) Y.row(static_cast<Eigen::Index>(k)) = pts[k].transpose();
  for (int round = 0; round < 1000; ++round) {  // projection converges linearly
    Eigen::MatrixXd B(pts.size(), n + 1);
    for (size_t k = 0; k < pts.size(); ++k) B.row(static_cast<Eigen::Index>(k)) = bernstein(n, t[k], 0).row(0);
    P = B.colPivHouseholderQr().solve(Y);
    double moved = 0;
    for (size_t k = 0; k < pts.size(); ++k) {
      const double next = project(P, pts[k], t[k]);
      moved = std::max(moved, std::abs(next - t[k]));
      t[k] = next;
    }
    if (moved < 1e-9) break;
  }
  return P;
}

// Where side a's curve continued past its end and side b's continued before its start come
// closest (each continued by up to three times its own length); false when that is farther
// apart than `gap`.
bool extrapolatedCorner(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b, double gap, Eigen::Vector3d& corner) {
  const Eigen::MatrixX3d A = ownCurve(a), B = ownCurve(b);
  double s0 = 1, s1 = 4, r0 = -3, r1 = 0, bestS = 1, bestR = 0, best = 1e300;
  for (int level = 0; level < 6; ++level) {
    const int g = 40;
    for (int i = 0; i <= g; ++i)
      for (int j = 0; j <= g; ++j) {
        const double s = s0 + (s1 - s0) * i / g, r = r0 + (r1 - r0) * j / g;
        const double d = (casteljau(A, s) - casteljau(B, r)).norm();
        if (d < best) best = d, bestS = s, bestR = r;
      }
    const double hs = 2 * (s1 - s0) / g, hr = 2 * (r1 - r0) / g;
    s0 = std::max(1.0, bestS - hs), s1 = std::min(4.0, bestS + hs), r0 = std::max(-3.0, bestR - hr), r1 = std::min(0.0, bestR + hr);
  }
  if (best > gap) return false;
  corner = 0.5 * (casteljau(A, bestS) + casteljau(B, bestR));
  return true;
}

}  // namespace

Eigen::Vector3d GuidingFrame::point(Side side, double t) const {
  const int i = static_cast<int>(side);
  if (!labeled[i]) throw Error("the guiding frame has no curve on that side (it is not labeled)");
  return curvePoint(control[i], t);
}

GuidingFrame fitGuidingFrame(const LabeledSides& sides, const GuidingFrameOptions& o) {
  GuidingFrame f;
  Eigen::AlignedBox3d box;
  int labeledSides = 0;
  std::size_t total = 0;
  static const char* names[4] = {"South", "East", "North", "West"};
  for (int i = 0; i < 4; ++i) {
    const auto& pts = sides.points[i];
    f.labeled[i] = !pts.empty();
    if (!f.labeled[i]) continue;
    if (pts.size() < 2) throw Error(std::string("the ") + names[i] + " side has only one point; a labeled side needs at least two");
    for (const auto& p : pts) {
      if (!p.allFinite()) throw Error(std::string("a point of the ") + names[i] + " side is not finite");
      box.extend(p);
    }
    ++labeledSides;
    total += pts.size();
  }
  if (labeledSides < 2) throw Error("label at least two sides (N, E, S or W) to fit a guiding frame");
  const double diagonal = std::max(box.diagonal().norm(), 1e-300);

  // Missing corners (two labeled sides whose labels stop more than three point spacings short of
  // their common corner): where the sides' own cubic fits, continued, come closest, if they come
  // within 5% of the diagonal (else, as for nearly parallel sides, the frame's least squares place
  // it). Such a corner is held while the frame is fitted: left to the shared least squares, the
  // data barely determine it (a labeled stretch met within tolerance can be continued in many
  // ways) and it settled 0.47 off on a cylinder with a cut corner. Ends a few spacings apart are
  // a corner the data already determine.
  const auto spacing = [&](int k) {
    const auto& p = sides.points[k];
    double len = 0;
    for (size_t q = 1; q < p.size(); ++q) len += (p[q] - p[q - 1]).norm();
    return len / static_cast<double>(p.size() - 1);
  };
  std::array<bool, 4> heldEnd{};
  std::array<Eigen::Vector3d, 4> heldCorner;
  for (int i = 0; i < 4; ++i) {
    const int j = (i + 1) % 4;
    if (!f.labeled[i] || !f.labeled[j]) continue;
    if ((sides.points[i].back() - sides.points[j].front()).norm() <= 3 * std::max(spacing(i), spacing(j))) continue;
    Eigen::Vector3d corner;
    if (extrapolatedCorner(sides.points[i], sides.points[j], 0.05 * diagonal, corner)) heldEnd[i] = true, heldCorner[i] = corner;
  }

  // Chord-length parameters to start, over the side up to a held corner.
  for (int i = 0; i < 4; ++i) {
    if (!f.labeled[i]) continue;
    const auto& pts = sides.points[i];
    std::vector<double> t(pts.size(), 0.0);
    for (size_t k = 1; k < pts.size(); ++k) t[k] = t[k - 1] + (pts[k] - pts[k - 1]).norm();
    double length = t.back(), offset = 0;
    if (heldEnd[i]) length += (heldCorner[i] - pts.back()).norm();
    if (heldEnd[(i + 3) % 4]) offset = (heldCorner[(i + 3) % 4] - pts.front()).norm(), length += offset;
    for (double& x : t) x = length > 0 ? (x + offset) / length : 0.0;
    f.parameters[i] = t;
  }

  for (int n = 1;; ++n) {
    f.degree = n;
    // Variables: control points, a side's last one shared with the next side's first when both are labeled.
    std::array<std::vector<int>, 4> var;
    int m = 0;
    for (int i = 0; i < 4; ++i)
      if (f.labeled[i]) var[i].assign(n + 1, -1), var[i][0] = m++;
    for (int i = 0; i < 4; ++i) {
      if (!f.labeled[i]) continue;
      for (int k = 1; k < n; ++k) var[i][k] = m++;
      var[i][n] = f.labeled[(i + 1) % 4] ? var[(i + 1) % 4][0] : m++;
    }
    const Eigen::MatrixXd K = bendingMatrix(n);
    // λ per point and relative to the bending matrix's scale, which grows as n⁴ with the degree.
    const double lambda = o.bending * static_cast<double>(total) / std::max(1.0, K.cwiseAbs().maxCoeff());
    double best = 1e300;
    int sinceBest = 0;
    GuidingFrame kept = f;
    for (int round = 0; round < o.roundsPerDegree; ++round) {
      // Squared distance to the tangent line at each point's footpoint plus a thousandth of the
      // point distance, after a first round of point distance alone: projection with point
      // distance converges linearly and stalled short of curves the data determines exactly.
      const bool tangent = round > 0;
      Eigen::MatrixXd A = Eigen::MatrixXd::Zero(3 * m, 3 * m);
      Eigen::VectorXd b = Eigen::VectorXd::Zero(3 * m);
      for (int i = 0; i < 4; ++i) {
        if (!f.labeled[i]) continue;
        for (size_t j = 0; j < sides.points[i].size(); ++j) {
          const Eigen::MatrixXd basis = bernstein(n, f.parameters[i][j], 1);
          Eigen::Matrix3d W = Eigen::Matrix3d::Identity();
          // A point whose footpoint is an end of its curve may lie beyond it: its residual runs
          // along the tangent, which the tangent distance would ignore; it keeps the point distance.
          const double t = f.parameters[i][j];
          if (tangent && t > 0 && t < 1) {
            const Eigen::Vector3d d = (basis.row(1) * f.control[i]).transpose();
            if (d.norm() > 0) W -= 0.999 * d.normalized() * d.normalized().transpose();
          }
          const Eigen::Vector3d wl = W * sides.points[i][j];
          for (int k = 0; k <= n; ++k) {
            b.segment<3>(3 * var[i][k]) += basis(0, k) * wl;
            for (int l = 0; l <= n; ++l) A.block<3, 3>(3 * var[i][k], 3 * var[i][l]) += basis(0, k) * basis(0, l) * W;
          }
        }
        for (int k = 0; k <= n; ++k)
          for (int l = 0; l <= n; ++l) A.block<3, 3>(3 * var[i][k], 3 * var[i][l]) += lambda * K(k, l) * Eigen::Matrix3d::Identity();
      }
      const double hold = 1e8 * std::max(1.0, A.diagonal().cwiseAbs().maxCoeff());
      for (int i = 0; i < 4; ++i)
        if (heldEnd[i]) {
          A.block<3, 3>(3 * var[i][n], 3 * var[i][n]) += hold * Eigen::Matrix3d::Identity();
          b.segment<3>(3 * var[i][n]) += hold * heldCorner[i];
        }
      const Eigen::VectorXd x = A.ldlt().solve(b);
      if (!x.allFinite()) throw Error("the guiding frame's least-squares system is singular: the labeled points are degenerate");
      Eigen::MatrixX3d X(m, 3);
      for (int v = 0; v < m; ++v) X.row(v) = x.segment<3>(3 * v).transpose();
      double sum = 0;
      f.maxDeviation = 0;
      for (int i = 0; i < 4; ++i) {
        if (!f.labeled[i]) continue;
        f.control[i].resize(n + 1, 3);
        for (int k = 0; k <= n; ++k) f.control[i].row(k) = X.row(var[i][k]);
        for (size_t j = 0; j < sides.points[i].size(); ++j) {
          f.parameters[i][j] = project(f.control[i], sides.points[i][j], f.parameters[i][j]);
          const double d = (curvePoint(f.control[i], f.parameters[i][j]) - sides.points[i][j]).norm();
          f.maxDeviation = std::max(f.maxDeviation, d);
          sum += d * d;
        }
      }
      ++f.rounds;
      const double rms = std::sqrt(sum / static_cast<double>(total));
      f.rmsDeviation = rms / diagonal;
      f.maxDeviation /= diagonal;
      // The rounds need not improve monotonically: keep the best, and leave this degree once ten
      // rounds have not improved on it by 1%, or as soon as it meets the tolerance.
      if (rms < best) {
        if (rms < 0.99 * best) sinceBest = 0;
        best = rms;
        kept = f;
      }
      if (f.maxDeviation <= o.tolerance || ++sinceBest >= 10) break;
    }
    kept.rounds = f.rounds;
    f = kept;
    if (f.maxDeviation <= o.tolerance || n >= o.maxDegree) break;  // else one degree more, from these parameters
  }
  return f;
}

}  // namespace holefill

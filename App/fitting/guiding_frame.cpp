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

  // Chord-length parameters to start.
  for (int i = 0; i < 4; ++i) {
    if (!f.labeled[i]) continue;
    const auto& pts = sides.points[i];
    std::vector<double> t(pts.size(), 0.0);
    for (size_t k = 1; k < pts.size(); ++k) t[k] = t[k - 1] + (pts[k] - pts[k - 1]).norm();
    for (double& x : t) x = t.back() > 0 ? x / t.back() : 0.0;
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

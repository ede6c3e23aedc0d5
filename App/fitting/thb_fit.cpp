#include "fitting/thb_fit.h"

#include <Eigen/Sparse>
#include <algorithm>
#include <cmath>
#include <set>

#include "fill/fairness_energy.h"
#include "geometry/bspline_basis.h"
#include "geometry/error.h"
#include "geometry/json_writer.h"
#include "geometry/surface_projection.h"

namespace holefill {

void ThbFitResult::writeFields(JsonWriter& j) const {
  j.key("iterations").beginArray();
  for (const auto& h : history)
    j.beginObject().field("dof", h.dof).field("mse", h.mse).field("max_error", h.maxError).field("refined_cells", h.refinedCells)
        .field("corrected_parameters", h.correctedParameters).endObject();
  j.endArray().field("levels", space.levels()).field("met_tolerance", metTolerance).field("folds", folds);
  j.field("diagonal", diagonal).field("relative_tolerance", relativeTolerance).field("tolerance", relativeTolerance * diagonal);
}

std::string ThbFitResult::toJson() const {
  JsonWriter j;
  j.beginObject();
  writeFields(j);
  j.endObject();
  return j.str();
}

ThbFitResult fitThb(const Eigen::MatrixX3d& points, const Eigen::MatrixX2d& uv0, const ThbFitOptions& o) {
  const Eigen::Index n = points.rows();
  if (uv0.rows() != n) throw Error("the parameters do not match the points in number");
  if (!points.allFinite() || !uv0.allFinite()) throw Error("the cloud or its parameters have a non-finite value");
  if (uv0.minCoeff() < -1e-12 || uv0.maxCoeff() > 1 + 1e-12) throw Error("the parameters must lie in [0, 1]²");
  ThbFitResult r;
  r.space = ThbSpace(o.degree, o.baseCells, o.baseCells);
  if (n < static_cast<Eigen::Index>(r.space.functions().size()))
    throw Error("the cloud has " + std::to_string(n) + " points, fewer than the " + std::to_string(r.space.functions().size()) + " functions of the base space");
  const double diagonal = std::max(1e-300, (points.colwise().maxCoeff() - points.colwise().minCoeff()).norm());
  r.diagonal = diagonal;
  r.relativeTolerance = o.relativeTolerance;
  r.uv = uv0.cwiseMax(0.0).cwiseMin(1.0);
  for (int it = 0;; ++it) {
    ThbSpace& s = r.space;
    const int L = s.levels() - 1;
    const std::vector<double> Uu = clampedUniformKnots(s.degree(), s.cellsU(L), 0, 1), Uv = clampedUniformKnots(s.degree(), s.cellsV(L), 0, 1);
    const Eigen::SparseMatrix<double> T = s.finestMap();
    const int p = s.degree(), nvFine = static_cast<int>(Uv.size()) - p - 1;
    // Data rows in the finest basis, mapped to the active functions.
    std::vector<Eigen::Triplet<double>> bt;
    for (Eigen::Index k = 0; k < n; ++k) {
      const int su = findSpan(Uu, p, r.uv(k, 0)), sv = findSpan(Uv, p, r.uv(k, 1));
      const Eigen::MatrixXd bu = basisDerivatives(Uu, p, su, r.uv(k, 0), 0), bv = basisDerivatives(Uv, p, sv, r.uv(k, 1), 0);
      for (int a = 0; a <= p; ++a)
        for (int b = 0; b <= p; ++b) bt.emplace_back(static_cast<int>(k), (su - p + a) * nvFine + (sv - p + b), bu(0, a) * bv(0, b));
    }
    Eigen::SparseMatrix<double> Bf(n, T.rows());
    Bf.setFromTriplets(bt.begin(), bt.end());
    const Eigen::SparseMatrix<double> B = Bf * T;
    Eigen::SparseMatrix<double> N = B.transpose() * B;
    const Eigen::SparseMatrix<double> E = T.transpose() * fairnessMatrix(p, Uu, p, Uv, FairnessWeights{1.0, 0.0}) * T;
    const double scale = std::max(1e-300, N.diagonal().maxCoeff()) / std::max(1e-300, Eigen::VectorXd(E.diagonal()).maxCoeff());
    N += o.smoothing * scale * E;
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(N);
    if (solver.info() != Eigen::Success) throw Error("the THB fitting system is singular: too few points for the refined cells");
    r.coefficients = solver.solve(B.transpose() * points);
    if (!r.coefficients.allFinite()) throw Error("the THB fit failed (non-finite coefficients)");
    // The surface at the finest level, and the errors.
    r.surface.degreeU = r.surface.degreeV = p;
    r.surface.knotsU = Uu;
    r.surface.knotsV = Uv;
    r.surface.poles = T * r.coefficients;
    ThbFitIteration h;
    h.dof = static_cast<int>(s.functions().size());
    Eigen::VectorXd err = ((B * r.coefficients) - points).rowwise().norm() / diagonal;
    h.mse = err.squaredNorm() / static_cast<double>(n);
    h.maxError = err.maxCoeff();
    // One parameter correction: a point's footpoint, kept only where it is closer.
    if (o.correctParameters) {
      for (Eigen::Index k = 0; k < n; ++k) {
        Eigen::Vector2d q = r.uv.row(k).transpose();
        const double d = projectPointFrom(r.surface, points.row(k).transpose(), q) / diagonal;
        if (d < err[k] - 1e-15) r.uv.row(k) = q.transpose(), err[k] = d, ++h.correctedParameters;
      }
    }
    r.metTolerance = h.maxError <= o.relativeTolerance;
    r.errors = err;
    if (r.metTolerance || it + 1 >= o.maxIterations) {
      r.history.push_back(h);
      break;
    }
    // Refine the active cells holding points above the tolerance, with their neighbours.
    std::map<int, std::set<std::pair<int, int>>> mark;  // level → cells
    for (Eigen::Index k = 0; k < n; ++k) {
      if (err[k] <= o.relativeTolerance) continue;
      for (int l = s.levels() - 1; l >= 0; --l) {
        const int i = std::min(s.cellsU(l) - 1, static_cast<int>(r.uv(k, 0) * s.cellsU(l)));
        const int j = std::min(s.cellsV(l) - 1, static_cast<int>(r.uv(k, 1) * s.cellsV(l)));
        if (!s.inDomain(l, i, j)) continue;
        if (l + 1 >= o.maxLevels) break;
        for (int di = -1; di <= 1; ++di)
          for (int dj = -1; dj <= 1; ++dj)
            if (s.inDomain(l, i + di, j + dj)) mark[l].insert({i + di, j + dj});
        break;
      }
    }
    for (const auto& [l, cells] : mark) {
      std::vector<std::pair<int, int>> fresh;
      for (const auto& [i, j] : cells)  // cells whose children are all in Ω^{l+1} already are refined
        if (!(s.inDomain(l + 1, 2 * i, 2 * j) && s.inDomain(l + 1, 2 * i + 1, 2 * j + 1))) fresh.push_back({i, j});
      if (!fresh.empty()) s.refine(l, fresh), h.refinedCells += static_cast<int>(fresh.size());
    }
    r.history.push_back(h);
    if (h.refinedCells == 0 && !o.correctParameters) break;  // nothing left to change
  }
  // Folds: the normal on a grid against the points' best-fit plane normal.
  const Eigen::MatrixX3d q = points.rowwise() - points.colwise().mean();
  const Eigen::Vector3d planeNormal = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(q.transpose() * q).eigenvectors().col(0);
  int positive = 0, negative = 0;
  for (int i = 0; i <= 64; ++i)
    for (int j = 0; j <= 64; ++j) {
      const auto d = r.surface.derivatives(i / 64.0, j / 64.0, 1);
      const double s = d[1][0].cross(d[0][1]).dot(planeNormal);
      (s > 0 ? positive : negative)++;
    }
  r.folds = std::min(positive, negative);  // the minority side: the orientation itself is arbitrary
  return r;
}

}  // namespace holefill

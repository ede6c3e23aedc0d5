#include "mesh/laplacian_fairing.h"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <algorithm>

#include "geometry/error.h"

namespace holefill {

void fairLaplacian(HolePatch& patch, const std::vector<std::vector<Eigen::Vector3d>>& outerRing,
                   const LaplacianFairingOptions& options) {
  const int nb = patch.boundaryCount;
  const int np = static_cast<int>(patch.points.size());
  const int nu = np - nb;
  if (options.order <= 0 || nu <= 0) return;

  // Local index space: patch vertices, then the fixed outer ring.
  std::vector<Eigen::Vector3d> points = patch.points;
  std::vector<std::vector<int>> adjacent(np);
  auto link = [&](int a, int b) {
    if (std::find(adjacent[a].begin(), adjacent[a].end(), b) == adjacent[a].end()) adjacent[a].push_back(b);
  };
  for (const auto& t : patch.triangles)
    for (int k = 0; k < 3; ++k) { link(t[k], t[(k + 1) % 3]); link(t[(k + 1) % 3], t[k]); }
  for (int b = 0; b < nb; ++b)
    for (const Eigen::Vector3d& q : outerRing[b]) {
      points.push_back(q);
      adjacent[b].push_back(static_cast<int>(points.size()) - 1);
    }
  const int nAll = static_cast<int>(points.size());

  // Uniform Laplacian rows for the patch's vertices (outer-ring rows are never needed: no new
  // vertex is adjacent to the outer ring).
  std::vector<Eigen::Triplet<double>> lt;
  for (int i = 0; i < np; ++i) {
    if (adjacent[i].empty()) continue;
    const double w = 1.0 / static_cast<double>(adjacent[i].size());
    lt.emplace_back(i, i, -1.0);
    for (int j : adjacent[i]) lt.emplace_back(i, j, w);
  }
  Eigen::SparseMatrix<double, Eigen::RowMajor> L(nAll, nAll);
  L.setFromTriplets(lt.begin(), lt.end());
  Eigen::SparseMatrix<double, Eigen::RowMajor> M = L;
  for (int k = 1; k < options.order; ++k) M = Eigen::SparseMatrix<double, Eigen::RowMajor>(L * M);

  // Each new vertex moves only along its normal, x_i = p_i + h_i n_i: the tangential layout
  // the refinement and smoothing made (and with it the triangle quality) is kept, and a
  // planar hole stays exactly planar. The scalar offsets h solve the least-squares problem
  // min Σ_c |M_uu (p_c + n_c∘h) + M_uk x_k,c|² (normal equations, SPD).
  std::vector<Eigen::Vector3d> normal(np, Eigen::Vector3d::Zero());
  for (const auto& t : patch.triangles) {
    double a2;
    const Eigen::Vector3d n = patchTriangleNormal(patch, t, &a2) * a2;
    for (int k = 0; k < 3; ++k) normal[t[k]] += n;
  }
  for (auto& n : normal)
    if (n.norm() > 0) n.normalize();
  std::vector<Eigen::Triplet<double>> at;
  Eigen::MatrixX3d r = Eigen::MatrixX3d::Zero(nu, 3);  // M applied to the current positions
  for (int i = nb; i < np; ++i)
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(M, i); it; ++it) {
      const int j = static_cast<int>(it.col());
      // Σ_j M_ij = 0, so M x = Σ_j M_ij (x_j − x_i): exact zero in the directions the
      // neighbourhood does not vary in (a planar hole stays planar to the last bit).
      r.row(i - nb) += it.value() * (points[j] - points[i]).transpose();
      if (j >= nb && j < np)
        for (int c = 0; c < 3; ++c) at.emplace_back(3 * (i - nb) + c, j - nb, it.value() * normal[j][c]);
    }
  Eigen::SparseMatrix<double> B(3 * nu, nu);  // residual rows (vertex, coordinate) per offset
  B.setFromTriplets(at.begin(), at.end());
  Eigen::VectorXd rv(3 * nu);
  for (int i = 0; i < nu; ++i) rv.segment<3>(3 * i) = r.row(i).transpose();
  const Eigen::SparseMatrix<double> A = B.transpose() * B;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver;
  solver.compute(A);
  if (solver.info() != Eigen::Success) throw Error("the fairing system of the hole is singular");
  const Eigen::VectorXd h = solver.solve(-(B.transpose() * rv));
  if (solver.info() != Eigen::Success || !h.allFinite()) throw Error("the fairing solve of the hole failed");
  for (int i = 0; i < nu; ++i) patch.points[nb + i] += h[i] * normal[nb + i];
}

}  // namespace holefill

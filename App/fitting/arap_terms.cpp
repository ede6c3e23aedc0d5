#include "fitting/arap_terms.h"

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>

namespace holefill {

std::vector<ArapTerm> arapTerms(const Eigen::MatrixX3d& vertices, const Eigen::MatrixX3i& tri, double& reference) {
  std::vector<ArapTerm> terms;
  terms.reserve(3 * static_cast<size_t>(tri.rows()));
  reference = 0;
  for (int t = 0; t < tri.rows(); ++t) {
    const Eigen::Vector3d p[3] = {vertices.row(tri(t, 0)), vertices.row(tri(t, 1)), vertices.row(tri(t, 2))};
    const Eigen::Vector3d e1 = p[1] - p[0], e2 = p[2] - p[0];
    const double l1 = e1.norm();
    const Eigen::Vector2d x[3] = {{0, 0}, {l1, 0}, {e1.dot(e2) / l1, e1.cross(e2).norm() / l1}};
    for (int k = 0; k < 3; ++k) {
      const int a = (k + 1) % 3, b = (k + 2) % 3;  // edge opposite corner k
      const Eigen::Vector2d u = x[a] - x[k], v = x[b] - x[k];
      const double cot = u.dot(v) / std::max(std::abs(u.x() * v.y() - u.y() * v.x()), 1e-300);
      const double w = std::max(0.5 * cot, 1e-4);
      terms.push_back({t, tri(t, a), tri(t, b), w, x[a] - x[b]});
      reference += w * (x[a] - x[b]).squaredNorm();
    }
  }
  return terms;
}

std::vector<Eigen::Matrix2d> arapRotations(const std::vector<ArapTerm>& terms, const Eigen::MatrixX2d& m, int triangles) {
  std::vector<Eigen::Matrix2d> R(triangles, Eigen::Matrix2d::Zero());
  for (const ArapTerm& term : terms) R[term.t] += term.w * (m.row(term.i) - m.row(term.j)).transpose() * term.x.transpose();
  for (auto& r : R) {
    Eigen::JacobiSVD<Eigen::Matrix2d> svd(r, Eigen::ComputeFullU | Eigen::ComputeFullV);
    Eigen::Matrix2d D = Eigen::Matrix2d::Identity();
    D(1, 1) = (svd.matrixU() * svd.matrixV().transpose()).determinant() < 0 ? -1 : 1;
    r = svd.matrixU() * D * svd.matrixV().transpose();
  }
  return R;
}

double signedArea(const Eigen::MatrixX2d& uv, const Eigen::Vector3i& t) {
  const Eigen::Vector2d a = uv.row(t[1]) - uv.row(t[0]), b = uv.row(t[2]) - uv.row(t[0]);
  return 0.5 * (a.x() * b.y() - a.y() * b.x());
}

std::vector<char> trianglesTurnedInInput(const Eigen::MatrixX3d& vertices, const Eigen::MatrixX3i& tri) {
  const Eigen::MatrixX3d vertexNormal = vertexNormals(TriangleMesh{vertices, tri});
  std::vector<char> turned(tri.rows(), 0);
  for (int t = 0; t < tri.rows(); ++t) {
    const Eigen::Vector3d a = vertices.row(tri(t, 0)), b = vertices.row(tri(t, 1)), c = vertices.row(tri(t, 2));
    const Eigen::Vector3d around = vertexNormal.row(tri(t, 0)) + vertexNormal.row(tri(t, 1)) + vertexNormal.row(tri(t, 2));
    turned[t] = (b - a).cross(c - a).dot(around) < 0;
  }
  return turned;
}

}  // namespace holefill

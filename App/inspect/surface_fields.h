// Exact differential quantities of a face sampled at parameter points: surface point,
// unit normal (face orientation applied), principal curvatures k1 >= k2 and the k1
// direction, evaluated from the surface's own second derivatives (do Carmo 3-3), never
// from a mesh. This is what the inspection maps (curvature colours, zebra stripes) show,
// so a fill's curvature defects are those of the B-spline, not of its triangulation.
// Evaluation runs on several threads (each with its own surface adaptor and cache).
#pragma once

#include <Eigen/Dense>
#include <TopoDS_Face.hxx>
#include <cstdint>
#include <vector>

namespace holefill {

// Curvature signs follow the CAD convention: positive where the surface bends away from its
// (outward) normal, so a ball with outward normals has k1 = k2 = +1/r and a bore negative mean curvature.
struct SurfaceFields {
  Eigen::MatrixX3d points, normals, d1;  // d1: unit direction of k1
  Eigen::VectorXd k1, k2;                // k1 >= k2; NaN where the surface is singular (no tangent plane)
  std::vector<std::uint8_t> regular;     // 0 at singular points (poles, apexes): normal is a placeholder

  Eigen::Index size() const { return points.rows(); }
  void resize(Eigen::Index n);
  // Rows [at, at + other.size()) := other (this must be large enough).
  void place(Eigen::Index at, const SurfaceFields& other);
};

// Fields of `face` at the rows of `uv`; threads <= 0 means all hardware threads.
SurfaceFields evaluateFaceFields(const TopoDS_Face& face, const Eigen::MatrixX2d& uv, int threads = 0);

// Threads to use for `n` independent evaluations when `requested` <= 0 means "all".
int workerThreads(Eigen::Index n, int requested);

}  // namespace holefill

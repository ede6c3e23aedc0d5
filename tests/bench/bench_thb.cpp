// Adaptive THB-spline fitting against uniform B-spline refinement on a real scan-like cloud
// (bidgcn.md sec. 5, 6.6): the vertices of a region of the Stanford bunny (CGAL's bunny00.off;
// a 0.25-ball about a vertex on its back, every normal there within 76° of the centre's, so the
// region is a height field over its plane) taken as a bare cloud — no boundary, no parameters.
// Its boundary is found (alpha shape), parameterized by chord length, the interior by the given
// method; then (a) the THB loop refines adaptively towards a tolerance, one parameter
// correction per iteration, and (b) the uniform B-spline spaces with 4·2^ℓ cells per direction
// are fitted from the same parameters with as many corrections as THB took to reach level ℓ.
// Prints a Markdown table of error against degrees of freedom and writes CSV files (curves, the
// hierarchical mesh, per-point errors) for scripts/bench.sh's pictures.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include "fitting/cloud_boundary.h"
#include "fitting/cloud_parameterization.h"
#include "fitting/thb_fit.h"
#include "mesh/mesh_io.h"

using namespace holefill;

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: holefill_bench_thb bunny00.off OUTDIR [method] [centre vertex] [radius]\n");
    return 2;
  }
  const std::string method = argc > 3 ? argv[3] : "shape";
  const int centre = argc > 4 ? std::atoi(argv[4]) : 3449;
  const double radius = argc > 5 ? std::atof(argv[5]) : 0.25;
  const std::string out = argv[2];
  const TriangleMesh mesh = readMesh(argv[1]);
  const Eigen::RowVector3d c = mesh.vertices.row(centre);
  std::vector<Eigen::RowVector3d> kept;
  for (Eigen::Index k = 0; k < mesh.vertices.rows(); ++k)
    if ((mesh.vertices.row(k) - c).norm() < radius) kept.push_back(mesh.vertices.row(k));
  Eigen::MatrixX3d p(kept.size(), 3);
  for (size_t k = 0; k < kept.size(); ++k) p.row(k) = kept[k];

  const auto t0 = std::chrono::steady_clock::now();
  const CloudBoundary b = detectCloudBoundary(p);
  const Eigen::MatrixX2d buv = boundaryChordParameters(p, b.boundary);
  CloudParameterizationOptions po;
  po.weights = cloudWeightsByName(method);
  const CloudParameterization param = parameterizeCloud(p, b.boundary, buv, po);
  const double paramSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  ThbFitOptions thb;
  thb.relativeTolerance = 2e-4;  // of the region's diagonal: about the scan's own noise
  thb.maxIterations = 10;
  thb.maxLevels = 6;
  const auto t1 = std::chrono::steady_clock::now();
  const ThbFitResult r = fitThb(p, param.uv, thb);
  const double thbSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();

  std::printf("Region: %d points (%d found on the boundary), %s parameters in %.2f s. Errors relative to the region's diagonal (%.4g).\n\n",
              int(p.rows()), b.count, method.c_str(), paramSeconds, r.diagonal);
  std::printf("| fit | step | degrees of freedom | MSE | max error | time (s) |\n|---|---|---|---|---|---|\n");
  std::ofstream curves(out + "/thb_curves.csv");
  curves << "fit,dof,mse,max_error\n";
  for (size_t i = 0; i < r.history.size(); ++i) {
    const auto& h = r.history[i];
    std::printf("| THB (adaptive) | iteration %zu | %d | %.3e | %.3e | %s |\n", i + 1, h.dof, h.mse, h.maxError,
                i + 1 == r.history.size() ? (std::to_string(thbSeconds).substr(0, 5)).c_str() : "");
    curves << "thb," << h.dof << "," << h.mse << "," << h.maxError << "\n";
  }
  for (int level = 0; level < thb.maxLevels - 1; ++level) {
    ThbFitOptions u = thb;
    u.baseCells = 4 << level;
    u.maxLevels = 1;
    u.maxIterations = level + 1;
    const auto t2 = std::chrono::steady_clock::now();
    try {
      const ThbFitResult f = fitThb(p, param.uv, u);
      const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t2).count();
      const auto& h = f.history.back();
      std::printf("| uniform B-spline | %d×%d cells | %d | %.3e | %.3e | %.3f |\n", u.baseCells, u.baseCells, h.dof, h.mse, h.maxError, s);
      curves << "uniform," << h.dof << "," << h.mse << "," << h.maxError << "\n";
    } catch (const std::exception& e) {
      std::printf("| uniform B-spline | %d×%d cells | — | failed: %s | | |\n", u.baseCells, u.baseCells, e.what());
    }
  }
  std::ofstream cells(out + "/thb_cells.csv");
  cells << "level,u0,v0,u1,v1\n";
  for (const auto& [l, i, j] : r.space.leafCells())
    cells << l << "," << double(i) / r.space.cellsU(l) << "," << double(j) / r.space.cellsV(l) << "," << double(i + 1) / r.space.cellsU(l) << ","
          << double(j + 1) / r.space.cellsV(l) << "\n";
  std::ofstream pts(out + "/thb_points.csv");
  pts << "x,y,z,u,v,error,boundary\n";
  for (Eigen::Index k = 0; k < p.rows(); ++k)
    pts << p(k, 0) << "," << p(k, 1) << "," << p(k, 2) << "," << r.uv(k, 0) << "," << r.uv(k, 1) << "," << r.errors[k] << "," << b.boundary[k] << "\n";
  return 0;
}

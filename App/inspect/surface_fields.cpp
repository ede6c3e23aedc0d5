#include "inspect/surface_fields.h"

#include <BRepAdaptor_Surface.hxx>
#include <TopoDS.hxx>
#include <algorithm>
#include <exception>
#include <limits>
#include <thread>

#include "geometry/differential_geometry.h"
#include "geometry/occt_bridge.h"

namespace holefill {

void SurfaceFields::resize(Eigen::Index n) {
  points.resize(n, 3);
  normals.resize(n, 3);
  d1.resize(n, 3);
  k1.resize(n);
  k2.resize(n);
  regular.assign(static_cast<size_t>(n), 1);
}

void SurfaceFields::place(Eigen::Index at, const SurfaceFields& o) {
  const Eigen::Index n = o.size();
  points.middleRows(at, n) = o.points;
  normals.middleRows(at, n) = o.normals;
  d1.middleRows(at, n) = o.d1;
  k1.segment(at, n) = o.k1;
  k2.segment(at, n) = o.k2;
  std::copy(o.regular.begin(), o.regular.end(), regular.begin() + at);
}

int workerThreads(Eigen::Index n, int requested) {
  const int hw = std::max(1u, std::thread::hardware_concurrency());
  const int want = requested > 0 ? requested : hw;
  // Below a few thousand samples a thread costs more than it saves.
  return static_cast<int>(std::max<Eigen::Index>(1, std::min<Eigen::Index>(want, n / 4096)));
}

namespace {

void evaluateRange(const TopoDS_Face& face, const Eigen::MatrixX2d& uv, Eigen::Index begin, Eigen::Index end,
                   SurfaceFields& f) {
  const BRepAdaptor_Surface s(face, false);  // own adaptor per thread: its B-spline cache is mutable
  const bool reversed = face.Orientation() == TopAbs_REVERSED;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (Eigen::Index i = begin; i < end; ++i) {
    const SurfaceJet j = faceJet(s, reversed, uv(i, 0), uv(i, 1));
    f.points.row(i) = j.p;
    Eigen::Vector3d n;
    // unitNormal's test is relative to |su||sv|, which a pole (su ~ 1e-16 |sv|) passes: test against the larger one.
    const double big = std::max(j.su.squaredNorm(), j.sv.squaredNorm());
    if (j.su.cross(j.sv).norm() <= 1e-12 * big || !unitNormal(j, n)) {
      f.regular[static_cast<size_t>(i)] = 0;
      f.normals.row(i).setZero();
      f.d1.row(i).setZero();
      f.k1(i) = f.k2(i) = nan;
      continue;
    }
    // principalCurvatures signs by II = S'' . n (a ball with outward n is negative): flip to the CAD convention.
    const PrincipalCurvatures pc = principalCurvatures(j, n);
    f.normals.row(i) = n;
    f.d1.row(i) = pc.d2;
    f.k1(i) = -pc.k2;
    f.k2(i) = -pc.k1;
  }
}

}  // namespace

SurfaceFields evaluateFaceFields(const TopoDS_Face& face, const Eigen::MatrixX2d& uv, int threads) {
  SurfaceFields f;
  const Eigen::Index n = uv.rows();
  f.resize(n);
  const int t = workerThreads(n, threads);
  if (t == 1) {
    evaluateRange(face, uv, 0, n, f);
    return f;
  }
  // An OCCT exception must not escape a worker (std::terminate would take FreeCAD down).
  std::vector<std::exception_ptr> errors(static_cast<size_t>(t));
  std::vector<std::thread> pool;
  for (int k = 0; k < t; ++k)
    pool.emplace_back([&, k] {
      try {
        evaluateRange(face, uv, n * k / t, n * (k + 1) / t, f);
      } catch (...) {
        errors[static_cast<size_t>(k)] = std::current_exception();
      }
    });
  for (auto& th : pool) th.join();
  for (const auto& e : errors)
    if (e) std::rethrow_exception(e);
  return f;
}

}  // namespace holefill

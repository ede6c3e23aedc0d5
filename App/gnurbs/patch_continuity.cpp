#include "gnurbs/patch_continuity.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace holefill {

namespace {

// Face parameters of the point at fraction t along edge k of a face, from corner k to k+1.
Eigen::Vector2d onEdge(int k, double t) {
  static const double cu[4] = {0, 1, 1, 0}, cv[4] = {0, 0, 1, 1};
  const int l = (k + 1) % 4;
  return {cu[k] + t * (cu[l] - cu[k]), cv[k] + t * (cv[l] - cv[k])};
}

}  // namespace

std::vector<CageEdgeContinuity> cageEdgeContinuity(const QuadCage& cage, const CageTopology& topo, const FaceJetFunction& jet,
                                                   int samples, double scale) {
  std::map<std::pair<int, int>, CageEdgeContinuity> edges;
  for (int f = 0; f < topo.faceCount(); ++f)
    for (int k = 0; k < 4; ++k) {
      const int g = topo.acrossFace(f, k), m = topo.acrossEdge(f, k);
      const int a = cage.quads(f, k), b = cage.quads(f, (k + 1) % 4);
      if (g < 0 || a > b) continue;  // boundary, or visited from the other side
      CageEdgeContinuity e;
      e.a = a;
      e.b = b;
      e.sharp = cage.isSharp(a, b);
      e.nearEP = topo.isExtraordinary(a) || topo.isExtraordinary(b);
      for (int s = 0; s < samples; ++s) {
        const double t = samples == 1 ? 0.5 : static_cast<double>(s) / (samples - 1);
        const Eigen::Vector2d pf = onEdge(k, t), pg = onEdge(m, 1 - t);  // the edge runs the other way in g
        const SurfaceJet jf = jet(f, pf.x(), pf.y()), jg = jet(g, pg.x(), pg.y());
        e.g0 = std::max(e.g0, (jf.p - jg.p).norm());
        Eigen::Vector3d nf, ng;
        if (!unitNormal(jf, nf) || !unitNormal(jg, ng)) {
          ++e.singularSamples;
          continue;
        }
        e.g1 = std::max(e.g1, std::atan2(nf.cross(ng).norm(), nf.dot(ng)));
        // Edge tangent from f's parameterisation along edge k.
        const Eigen::Vector2d dir = onEdge(k, 1) - onEdge(k, 0);
        const Eigen::Vector3d tangent = dir.x() * jf.su + dir.y() * jf.sv;
        const Eigen::Vector3d across = nf.cross(tangent);
        if (across.norm() < 1e-300) {
          ++e.singularSamples;
          continue;
        }
        const double kf = normalCurvature(jf, nf, across), kg = normalCurvature(jg, nf, across);
        e.maxCurvature = std::max({e.maxCurvature, std::abs(kf), std::abs(kg)});
        if (!e.sharp) e.g2 = std::max(e.g2, std::abs(kf - kg) / std::max(std::abs(kg), 1 / scale));
      }
      edges[{a, b}] = e;
    }
  std::vector<CageEdgeContinuity> out;
  for (auto& [key, e] : edges) out.push_back(e);
  return out;
}

}  // namespace holefill

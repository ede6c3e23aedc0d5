#include "learn/uvtran_data.h"

#include <algorithm>
#include <cmath>
#include <random>

#include "geometry/error.h"
#include "geometry/polygon2d.h"

namespace holefill::learn {

uint64_t uvtranSeed(UvtranSplit split, uint64_t index) {
  const uint64_t base = split == UvtranSplit::Train ? 0 : split == UvtranSplit::Validation ? (1ull << 40) : (2ull << 40);
  return base + index;
}

std::vector<double> interiorKnots(const std::vector<double>& k) {
  HF_CHECK(k.size() == kUvtranGrid + 4, "a UVTran knot vector has 12 knots");
  return std::vector<double>(k.begin() + 4, k.begin() + 8);
}

std::vector<double> clampedCubicKnots(const std::vector<double>& interior) {
  HF_CHECK(interior.size() == kUvtranInteriorKnots, "a UVTran knot vector has 4 interior knots");
  std::vector<double> k(4, 0.0);
  std::vector<double> in = interior;
  std::sort(in.begin(), in.end());
  // Predicted knots may touch or cross: keep them strictly inside (0, 1) and apart.
  for (int i = 0; i < kUvtranInteriorKnots; ++i) {
    const double lo = (i == 0 ? 0.0 : in[i - 1]) + 0.02;
    in[i] = std::clamp(in[i], lo, 0.98 - 0.02 * (kUvtranInteriorKnots - 1 - i));
  }
  k.insert(k.end(), in.begin(), in.end());
  k.insert(k.end(), 4, 1.0);
  return k;
}

namespace {

using Rng = std::mt19937_64;

double uni(Rng& g, double a, double b) { return std::uniform_real_distribution<double>(a, b)(g); }
bool chance(Rng& g, double p) { return uni(g, 0, 1) < p; }

// A near-isometric bending of the plane with height waves, placed anywhere in space.
struct Generator {
  double bendU = 0, bendV = 0;
  struct Wave { double a, wu, wv, phase; };
  std::vector<Wave> waves;
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d t = Eigen::Vector3d::Zero();
  double s = 1;
  Eigen::Matrix2d M = Eigen::Matrix2d::Identity();  // domain rotation/mirror about (0.5, 0.5)

  Eigen::Vector3d raw(double u, double v) const {
    const double x = u - 0.5, y = v - 0.5;
    double z = 0;
    for (const auto& w : waves) z += w.a * std::sin(w.wu * x + w.wv * y + w.phase);
    Eigen::Vector3d p(x, y, z);
    if (std::abs(bendU) > 1e-9) {  // roll the x direction onto a cylinder, z along its normal
      const double r = 1 / bendU, th = x * bendU;
      p = Eigen::Vector3d(r * std::sin(th) - z * std::sin(th), y, r * (1 - std::cos(th)) + z * std::cos(th));
    }
    if (std::abs(bendV) > 1e-9) {
      const double r = 1 / bendV, ph = y * bendV, h = p.z();
      p = Eigen::Vector3d(p.x(), r * std::sin(ph) - h * std::sin(ph), r * (1 - std::cos(ph)) + h * std::cos(ph));
    }
    return s * (R * p) + t;
  }
  Eigen::Vector3d operator()(double u, double v) const {
    const Eigen::Vector2d q = Eigen::Vector2d(0.5, 0.5) + M * Eigen::Vector2d(u - 0.5, v - 0.5);
    return raw(q.x(), q.y());
  }
};

const char* kFamilies[] = {"flat", "bumpy", "cylinder", "dome", "saddle"};

Generator drawGenerator(Rng& g, int f) {
  Generator G;
  auto sign = [&] { return chance(g, 0.5) ? 1.0 : -1.0; };
  double waveAmp = 0;
  switch (f) {
    case 0: waveAmp = uni(g, 0.0, 0.015); break;
    case 1: waveAmp = uni(g, 0.03, 0.1); break;
    case 2: G.bendU = sign() * uni(g, 1.0, 5.0); waveAmp = uni(g, 0, 0.03); break;
    case 3: G.bendU = uni(g, 0.8, 3.5); G.bendV = G.bendU * uni(g, 0.5, 1.2); waveAmp = uni(g, 0, 0.03); break;
    default: G.bendU = uni(g, 0.8, 3.5); G.bendV = -G.bendU * uni(g, 0.5, 1.2); waveAmp = uni(g, 0, 0.03); break;
  }
  if (f >= 3 && chance(g, 0.5)) G.bendU = -G.bendU, G.bendV = -G.bendV;
  const int nw = std::uniform_int_distribution<int>(1, 3)(g);
  for (int k = 0; k < nw; ++k) {
    const double w = uni(g, 2.0, 8.0), dir = uni(g, 0, 2 * M_PI);
    G.waves.push_back({waveAmp / std::sqrt(double(nw)) * uni(g, 0.5, 1.0), w * std::cos(dir), w * std::sin(dir),
                       uni(g, 0, 2 * M_PI)});
  }
  // Random placement: the canonical frame must undo it.
  Eigen::Quaterniond q(uni(g, -1, 1), uni(g, -1, 1), uni(g, -1, 1), uni(g, -1, 1));
  q.normalize();
  G.R = q.toRotationMatrix();
  G.t = Eigen::Vector3d(uni(g, -50, 50), uni(g, -50, 50), uni(g, -50, 50));
  G.s = std::exp(uni(g, std::log(0.1), std::log(100.0)));
  return G;
}

struct Pcurve {
  std::vector<Eigen::Vector2d> points;  // dense, closed, counter-clockwise
  std::vector<int> corners;             // dense indices of the corners
};

// A star-shaped N-gon with curved sides, reflex corners and bumps; centred at (0.5, 0.5).
bool drawPcurve(Rng& g, int dense, double rmsRadius, Pcurve& pc, int& sides) {
  const int N = std::uniform_int_distribution<int>(3, 8)(g);
  sides = N;
  const double offset = uni(g, 0, 2 * M_PI);
  std::vector<Eigen::Vector2d> V(N);
  for (int k = 0; k < N; ++k) {
    const double th = offset + 2 * M_PI * (k + uni(g, -0.3, 0.3)) / N;
    double r = uni(g, 0.75, 1.25);
    if (N >= 4 && chance(g, 0.2)) r *= uni(g, 0.45, 0.7);  // reflex corner
    V[k] = r * Eigen::Vector2d(std::cos(th), std::sin(th));
  }
  double perimeter = 0;
  for (int k = 0; k < N; ++k) perimeter += (V[(k + 1) % N] - V[k]).norm();
  pc.points.clear();
  pc.corners.clear();
  for (int k = 0; k < N; ++k) {
    const Eigen::Vector2d a = V[k], b = V[(k + 1) % N];
    const double len = (b - a).norm();
    const Eigen::Vector2d outward = Eigen::Vector2d((b - a).y(), -(b - a).x()) / len;
    const double bulge = chance(g, 0.4) ? 0.0 : uni(g, -0.25, 0.3) * len;
    const Eigen::Vector2d ctrl = 0.5 * (a + b) + 2 * bulge * outward;  // quadratic Bezier: bulge at mid
    const bool bump = chance(g, 0.2);
    const double bumpAmp = (chance(g, 0.5) ? 1 : -1) * uni(g, 0.03, 0.08) * len, bumpAt = uni(g, 0.3, 0.7);
    const int m = std::max(8, static_cast<int>(std::round(dense * len / perimeter)));
    pc.corners.push_back(static_cast<int>(pc.points.size()));
    for (int i = 0; i < m; ++i) {
      const double s = double(i) / m;
      Eigen::Vector2d p = (1 - s) * (1 - s) * a + 2 * s * (1 - s) * ctrl + s * s * b;
      if (bump) p += bumpAmp * std::exp(-0.5 * std::pow((s - bumpAt) / 0.08, 2)) * outward;
      pc.points.push_back(p);
    }
  }
  // Elongated holes (a removed fillet is a long strip): stretch along a random direction.
  if (chance(g, 0.4)) {
    const double a = uni(g, 1.0, 2.5), dir = uni(g, 0, M_PI);
    const Eigen::Vector2d d(std::cos(dir), std::sin(dir));
    for (auto& p : pc.points) p += (a - 1) * p.dot(d) * d;
  }
  Polygon2 coarse;
  for (size_t i = 0; i < pc.points.size(); i += 4) coarse.push_back(pc.points[i]);
  if (selfIntersects(coarse) || signedArea(coarse) <= 0) return false;
  Eigen::Vector2d c = Eigen::Vector2d::Zero();
  for (const auto& p : pc.points) c += p;
  c /= double(pc.points.size());
  double r2 = 0;
  for (const auto& p : pc.points) r2 += (p - c).squaredNorm();
  const double k = rmsRadius / std::sqrt(r2 / pc.points.size());
  for (auto& p : pc.points) {
    p = Eigen::Vector2d(0.5, 0.5) + k * (p - c);
    if (p.minCoeff() < 0.03 || p.maxCoeff() > 0.97) return false;
  }
  return true;
}

// Rotate/mirror the generator's domain so that at the centre S_u follows the frame's x axis
// and S_u x S_v the frame's z axis.
void alignDomain(Generator& G, const CanonicalFrame& F) {
  G.M.setIdentity();
  const double h = 1e-5;
  const Eigen::Vector3d gu = (G(0.5 + h, 0.5) - G(0.5 - h, 0.5)) / (2 * h);
  const Eigen::Vector3d gv = (G(0.5, 0.5 + h) - G(0.5, 0.5 - h)) / (2 * h);
  Eigen::Matrix<double, 3, 2> J;
  J << gu, gv;
  const Eigen::Vector2d d = (J.transpose() * J).ldlt().solve(J.transpose() * F.rotation.row(0).transpose());
  const double phi = std::atan2(d.y(), d.x());
  const double sigma = gu.cross(gv).dot(F.rotation.row(2).transpose()) >= 0 ? 1.0 : -1.0;
  Eigen::Matrix2d rot;
  rot << std::cos(phi), -std::sin(phi), std::sin(phi), std::cos(phi);
  G.M = rot * Eigen::Vector2d(1.0, sigma).asDiagonal();
}

}  // namespace

UvtranSample makeUvtranSample(uint64_t seed, const UvtranDataOptions& opt) {
  Rng g(seed * 0x9E3779B97F4A7C15ull + 0x2545F4914F6CDD1Dull);
  // The family is drawn once, so rejections (poles leaving the cube) do not skew the mix.
  const int family = std::uniform_int_distribution<int>(0, 4)(g);
  for (int attempt = 1; attempt <= opt.maxAttempts; ++attempt) {
    UvtranSample out;
    out.seed = seed;
    out.attempts = attempt;
    out.family = kFamilies[family];
    Generator G = drawGenerator(g, family);
    Pcurve pc;
    if (!drawPcurve(g, opt.densePcurveSamples, opt.pcurveRmsRadius, pc, out.sides)) continue;
    std::vector<double> knots[2];
    for (auto& k : knots) {
      std::vector<double> in;
      for (int i = 1; i <= kUvtranInteriorKnots; ++i) in.push_back(0.2 * i + uni(g, -0.07, 0.07));
      k = clampedCubicKnots(in);
    }
    // Structured perturbation (a boundary row/column shifted) and noise, in generator units.
    Eigen::MatrixX3d shift = Eigen::MatrixX3d::Zero(kUvtranGrid * kUvtranGrid, 3);
    if (chance(g, 0.5)) {
      const int side = std::uniform_int_distribution<int>(0, 3)(g);
      const Eigen::Vector3d dir = Eigen::Vector3d(uni(g, -1, 1), uni(g, -1, 1), uni(g, -1, 1)).normalized();
      const Eigen::Vector3d d = uni(g, 0.02, 0.08) * G.s * (G.R * dir);
      const bool second = chance(g, 0.3);
      for (int a = 0; a < kUvtranGrid; ++a)
        for (int depth = 0; depth < (second ? 2 : 1); ++depth) {
          const int line = side % 2 == 0 ? depth : kUvtranGrid - 1 - depth;
          const int i = side < 2 ? line : a, j = side < 2 ? a : line;
          shift.row(i * kUvtranGrid + j) += (depth == 0 ? 1.0 : 0.5) * d.transpose();
        }
    }
    const double noise = chance(g, 0.5) ? 0.002 * G.s : 0.0;
    std::normal_distribution<double> gauss(0.0, 1.0);
    for (int r = 0; r < shift.rows(); ++r)
      for (int c = 0; c < 3; ++c) shift(r, c) += noise * gauss(g);
    // The random start and direction along the loop that the canonical frame must undo.
    const int n = static_cast<int>(pc.points.size());
    const int start = std::uniform_int_distribution<int>(0, n - 1)(g);
    const bool reverse = chance(g, 0.5);

    // Align the domain to the frame of the boundary, rebuild, and align again to the frame of
    // the rebuilt boundary (perturbations move it a little).
    CanonicalFrame F = canonicalFrame([&] {
      std::vector<Eigen::Vector3d> l;
      for (const auto& p : pc.points) l.push_back(G(p.x(), p.y()));
      return l;
    }());
    BSplineSurface S;
    std::vector<Eigen::Vector2d> uv(n);
    std::vector<Eigen::Vector3d> loop(n);
    for (int pass = 0; pass < 2; ++pass) {
      alignDomain(G, F);
      S = BSplineSurface();
      S.knotsU = knots[0];
      S.knotsV = knots[1];
      S.poles.resize(kUvtranGrid * kUvtranGrid, 3);
      for (int i = 0; i < kUvtranGrid; ++i)
        for (int j = 0; j < kUvtranGrid; ++j) {
          const double gu = (knots[0][i + 1] + knots[0][i + 2] + knots[0][i + 3]) / 3;
          const double gv = (knots[1][j + 1] + knots[1][j + 2] + knots[1][j + 3]) / 3;
          S.poles.row(S.index(i, j)) = G(gu, gv).transpose() + shift.row(i * kUvtranGrid + j);
        }
      // pcurve in the aligned domain: G'(uv) = G(c + M (uv - c)) must hit the same loop.
      const Eigen::Matrix2d Minv = G.M.inverse();
      for (int k = 0; k < n; ++k) {
        const int src = reverse ? ((start - k) % n + n) % n : (start + k) % n;
        uv[k] = Eigen::Vector2d(0.5, 0.5) + Minv * (pc.points[src] - Eigen::Vector2d(0.5, 0.5));
        loop[k] = S.point(uv[k].x(), uv[k].y());
      }
      F = canonicalFrame(loop, opt.canonical);
    }
    const CanonicalBoundary cb = canonicalizeBoundary(loop, opt.canonical);
    bool inside = true;
    for (int r = 0; r < S.poles.rows() && inside; ++r) {
      const Eigen::Vector3d q = cb.frame.toCanonical(S.poles.row(r).transpose());
      S.poles.row(r) = q.transpose();
      inside = q.minCoeff() >= opt.poleMargin && q.maxCoeff() <= 1 - opt.poleMargin;
    }
    if (!inside) continue;
    out.surface = S;
    out.boundary = cb.points;
    for (double p : cb.loopParameter) {
      const int i = static_cast<int>(std::floor(p)) % n;
      const double f = p - std::floor(p);
      out.params.push_back((1 - f) * uv[i] + f * uv[(i + 1) % n]);
    }
    // Corners: the dense corner indices, moved through the start/direction shuffle, nearest sample.
    for (int c : pc.corners) {
      const int k = reverse ? ((start - c) % n + n) % n : ((c - start) % n + n) % n;
      int best = 0;
      double bestD = 1e300;
      for (size_t s = 0; s < cb.loopParameter.size(); ++s) {
        double d = std::abs(cb.loopParameter[s] - k);
        d = std::min(d, n - d);
        if (d < bestD) { bestD = d; best = static_cast<int>(s); }
      }
      out.cornerSamples.push_back(best);
    }
    std::sort(out.cornerSamples.begin(), out.cornerSamples.end());
    return out;
  }
  throw Error("UVTran data: no valid sample for seed " + std::to_string(seed) + " in " +
              std::to_string(opt.maxAttempts) + " attempts");
}

}  // namespace holefill::learn

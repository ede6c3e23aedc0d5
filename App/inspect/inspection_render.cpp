#include "inspect/inspection_render.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <thread>

#include "geometry/error.h"
#include "geometry/json_writer.h"

namespace holefill {

RenderMode renderModeFromString(const std::string& s) {
  if (s == "zebra") return RenderMode::Zebra;
  if (s == "curvature") return RenderMode::Curvature;
  if (s == "shaded") return RenderMode::Shaded;
  throw Error("unknown render mode '" + s + "': use zebra, curvature or shaded");
}

std::string toString(RenderMode m) {
  return m == RenderMode::Zebra ? "zebra" : m == RenderMode::Curvature ? "curvature" : "shaded";
}

ViewDirection viewFromString(const std::string& s) {
  using V = Eigen::Vector3d;
  const V z = V::UnitZ();
  if (s == "iso" || s == "isometric") return {V(-1, 1, -1).normalized(), z};
  if (s == "top") return {V(0, 0, -1), V::UnitY()};
  if (s == "bottom") return {V(0, 0, 1), -V::UnitY()};
  if (s == "front") return {V(0, 1, 0), z};
  if (s == "back") return {V(0, -1, 0), z};
  if (s == "right") return {V(-1, 0, 0), z};
  if (s == "left") return {V(1, 0, 0), z};
  std::stringstream ss(s);
  V d;
  char c1 = 0, c2 = 0;
  if ((ss >> d.x() >> c1 >> d.y() >> c2 >> d.z()) && c1 == ',' && c2 == ',' && ss.eof() && d.allFinite() && d.norm() > 0) {
    d.normalize();
    const V up = std::abs(d.dot(z)) > 0.99 ? V::UnitY() : z;
    return {d, up};
  }
  throw Error("unknown view '" + s + "': use iso, top, bottom, front, back, left, right or dx,dy,dz");
}

namespace {

using RGB8 = std::array<std::uint8_t, 3>;

RGB8 toRgb8(double r, double g, double b) {
  const auto q = [](double x) { return static_cast<std::uint8_t>(std::lround(std::clamp(x, 0.0, 1.0) * 255.0)); };
  return {q(r), q(g), q(b)};
}

struct Camera {
  Eigen::Vector3d view, right, up;
  double scale = 1, cx = 0, cy = 0;  // pixel = (x - cx) * scale + W/2, ...
  int width = 0, height = 0;
  Eigen::Vector3d project(const Eigen::Vector3d& p) const {
    return {(p.dot(right) - cx) * scale + 0.5 * width, 0.5 * height - (p.dot(up) - cy) * scale, p.dot(view)};
  }
};

Camera fitCamera(const InspectionMesh& m, const ViewDirection& v, int width, int height) {
  Camera c;
  c.view = v.view.normalized();
  c.right = c.view.cross(v.up);
  if (c.right.norm() < 1e-9) c.right = c.view.cross(Eigen::Vector3d::UnitX());
  c.right.normalize();
  c.up = c.right.cross(c.view).normalized();
  c.width = width;
  c.height = height;
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  for (Eigen::Index i = 0; i < m.fields.size(); ++i) {
    const Eigen::Vector3d p = m.fields.points.row(i);
    x0 = std::min(x0, p.dot(c.right)); x1 = std::max(x1, p.dot(c.right));
    y0 = std::min(y0, p.dot(c.up)); y1 = std::max(y1, p.dot(c.up));
  }
  c.cx = 0.5 * (x0 + x1);
  c.cy = 0.5 * (y0 + y1);
  const double w = std::max(x1 - x0, 1e-12), h = std::max(y1 - y0, 1e-12);
  c.scale = 0.92 * std::min(width / w, height / h);
  return c;
}

// Per-pixel triangle and barycentrics (deferred shading: every visible pixel is shaded once).
struct GBuffer {
  int w, h;
  std::vector<float> depth, b1, b2;
  std::vector<int> tri;
  GBuffer(int w_, int h_) : w(w_), h(h_), depth(static_cast<size_t>(w_) * h_, std::numeric_limits<float>::infinity()),
                            b1(depth.size()), b2(depth.size()), tri(depth.size(), -1) {}
};

void rasterize(const InspectionMesh& m, const std::vector<Eigen::Vector3d>& s, int rowBegin, int rowEnd,
               GBuffer& g) {
  for (Eigen::Index t = 0; t < m.triangles.rows(); ++t) {
    const Eigen::Vector3d &a = s[static_cast<size_t>(m.triangles(t, 0))], &b = s[static_cast<size_t>(m.triangles(t, 1))],
                          &c = s[static_cast<size_t>(m.triangles(t, 2))];
    const double area = (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
    if (std::abs(area) < 1e-12) continue;
    const int xa = std::max(0, static_cast<int>(std::floor(std::min({a.x(), b.x(), c.x()}))));
    const int xb = std::min(g.w - 1, static_cast<int>(std::ceil(std::max({a.x(), b.x(), c.x()}))));
    const int ya = std::max(rowBegin, static_cast<int>(std::floor(std::min({a.y(), b.y(), c.y()}))));
    const int yb = std::min(rowEnd - 1, static_cast<int>(std::ceil(std::max({a.y(), b.y(), c.y()}))));
    if (ya > yb) continue;
    for (int y = ya; y <= yb; ++y)
      for (int x = xa; x <= xb; ++x) {
        const double px = x + 0.5, py = y + 0.5;
        const double w1 = ((c.x() - a.x()) * (py - a.y()) - (c.y() - a.y()) * (px - a.x())) / -area;
        const double w2 = ((b.x() - a.x()) * (py - a.y()) - (b.y() - a.y()) * (px - a.x())) / area;
        const double w0 = 1.0 - w1 - w2;
        if (w0 < -1e-9 || w1 < -1e-9 || w2 < -1e-9) continue;
        const float z = static_cast<float>(w0 * a.z() + w1 * b.z() + w2 * c.z());
        const size_t k = static_cast<size_t>(y) * g.w + x;
        if (z < g.depth[k]) {
          g.depth[k] = z;
          g.tri[k] = static_cast<int>(t);
          g.b1[k] = static_cast<float>(w1);
          g.b2[k] = static_cast<float>(w2);
        }
      }
  }
}

void drawEdges(const InspectionMesh& m, const Camera& cam, const GBuffer& g, int thickness, std::vector<std::uint8_t>& mask) {
  const float bias = static_cast<float>(2e-3 * m.diagonal);
  for (const auto& line : m.edgePolylines)
    for (Eigen::Index i = 0; i + 1 < line.rows(); ++i) {
      const Eigen::Vector3d a = cam.project(line.row(i).transpose()), b = cam.project(line.row(i + 1).transpose());
      const int steps = std::max(1, static_cast<int>(std::ceil(std::max(std::abs(b.x() - a.x()), std::abs(b.y() - a.y())))));
      for (int k = 0; k <= steps; ++k) {
        const Eigen::Vector3d p = a + (b - a) * (static_cast<double>(k) / steps);
        for (int dy = 0; dy < thickness; ++dy)
          for (int dx = 0; dx < thickness; ++dx) {
            const int x = static_cast<int>(p.x()) + dx - thickness / 2, y = static_cast<int>(p.y()) + dy - thickness / 2;
            if (x < 0 || y < 0 || x >= g.w || y >= g.h) continue;
            const size_t q = static_cast<size_t>(y) * g.w + x;
            if (static_cast<float>(p.z()) <= g.depth[q] + bias) mask[q] = 1;
          }
      }
    }
}

// Runs fn(rowBegin, rowEnd) over [0, rows) in one band per hardware thread.
template <class F>
void inBands(int rows, F&& fn) {
  const int t = std::max(1, std::min(static_cast<int>(std::thread::hardware_concurrency()), rows / 64));
  std::vector<std::thread> pool;
  for (int k = 1; k < t; ++k) pool.emplace_back([&, k] { fn(rows * k / t, rows * (k + 1) / t); });
  fn(0, rows / t);
  for (auto& th : pool) th.join();
}

std::string quantityTitle(CurvatureQuantity q) {
  switch (q) {
    case CurvatureQuantity::Gaussian: return "GAUSSIAN CURVATURE";
    case CurvatureQuantity::Mean: return "MEAN CURVATURE";
    case CurvatureQuantity::MaxPrincipal: return "MAX PRINCIPAL CURVATURE";
    case CurvatureQuantity::MinPrincipal: return "MIN PRINCIPAL CURVATURE";
    case CurvatureQuantity::Direction: return "CURVATURE ALONG DIRECTION";
  }
  return "";
}

void drawLegend(RasterImage& im, const ColorScale& s, const std::string& title, int x0) {
  const int fs = std::max(1, im.height / 400), barTop = im.height / 6, barBottom = im.height * 5 / 6, barW = 6 * fs + 10;
  const RGB8 ink = {20, 20, 20};
  drawText(im, std::max(2, x0 - textWidth(title, fs) / 2), barTop - 16 * fs, title, fs, ink);
  for (int y = barTop; y < barBottom; ++y) {
    const double t = 1.0 - static_cast<double>(y - barTop) / (barBottom - barTop - 1);
    const auto c = s.color(s.low + t * (s.high - s.low));
    im.fillRect(x0, y, x0 + barW, y + 1, toRgb8(c[0], c[1], c[2]));
  }
  for (double v : s.ticks(6)) {
    const int y = barBottom - 1 - static_cast<int>(std::lround((v - s.low) / (s.high - s.low) * (barBottom - barTop - 1)));
    im.fillRect(x0 + barW, y, x0 + barW + 4 * fs, y + std::max(1, fs / 2), ink);
    drawText(im, x0 + barW + 6 * fs, y - 3 * fs, tickLabel(v), fs, ink);
  }
}

}  // namespace

RenderResult renderInspection(const InspectionMesh& m, const RenderOptions& o) {
  const auto t0 = std::chrono::steady_clock::now();
  if (o.width < 16 || o.height < 16 || o.width > 8192 || o.height > 8192)
    throw Error("image size must be between 16x16 and 8192x8192");
  if (o.supersample < 1 || o.supersample > 4) throw Error("supersample must be 1..4");
  if (o.stripes.count < 1 || o.stripes.count > 1000 || !(o.stripes.width > 0 && o.stripes.width < 1))
    throw Error("stripes need a count of 1..1000 and a width strictly between 0 and 1");
  if (m.fields.size() == 0 || m.triangles.rows() == 0) throw Error("nothing to render: the mesh is empty");
  RenderResult r;
  r.vertices = m.fields.size();
  r.triangles = m.triangles.rows();
  Eigen::VectorXd values;
  if (o.mode == RenderMode::Curvature) {
    values = curvatureValues(m.fields, o.quantity, o.curvatureDirection);
    r.scale = makeColorScale(values, isSigned(o.quantity), o.scale);
    r.valueMin = std::numeric_limits<double>::infinity();
    r.valueMax = -r.valueMin;
    for (Eigen::Index i = 0; i < values.size(); ++i)
      if (std::isfinite(values(i))) { r.valueMin = std::min(r.valueMin, values(i)); r.valueMax = std::max(r.valueMax, values(i)); }
  }
  const bool legend = o.legend && o.mode == RenderMode::Curvature;
  const int legendW = legend ? std::max(150, o.width / 5) : 0;
  const int ss = o.supersample, W = (o.width - legendW) * ss, H = o.height * ss;
  const Camera cam = fitCamera(m, o.view, W, H);
  GBuffer g(W, H);
  std::vector<Eigen::Vector3d> screen(static_cast<size_t>(m.fields.size()));
  for (Eigen::Index i = 0; i < m.fields.size(); ++i) screen[static_cast<size_t>(i)] = cam.project(m.fields.points.row(i).transpose());
  inBands(H, [&](int y0, int y1) { rasterize(m, screen, y0, y1, g); });
  std::vector<std::uint8_t> edgeMask(static_cast<size_t>(W) * H, 0);
  if (o.edges) drawEdges(m, cam, g, ss, edgeMask);
  const Eigen::Vector3d stripeDir = stripeDirection(o.stripes, cam.view, cam.up);

  std::vector<float> acc(static_cast<size_t>(o.width - legendW) * o.height * 3, 0.0f);
  // Bands of whole output rows, so no two threads add into the same pixel.
  inBands(o.height, [&](int oy0, int oy1) {
  for (int y = oy0 * ss; y < oy1 * ss; ++y)
    for (int x = 0; x < W; ++x) {
      const size_t k = static_cast<size_t>(y) * W + x;
      double col[3] = {1.0, 1.0, 1.0};
      if (edgeMask[k]) {
        col[0] = col[1] = col[2] = 0.12;
      } else if (g.tri[k] >= 0) {
        const int t = g.tri[k];
        const double w[3] = {1.0 - g.b1[k] - g.b2[k], g.b1[k], g.b2[k]};
        Eigen::Vector3d n = Eigen::Vector3d::Zero();
        double v = 0, vw = 0;
        for (int c = 0; c < 3; ++c) {
          const Eigen::Index vi = m.triangles(t, c);
          n += w[c] * m.fields.normals.row(vi).transpose();
          if (values.size() && std::isfinite(values(vi))) { v += w[c] * values(vi); vw += w[c]; }
        }
        if (n.norm() < 1e-12) {  // all corners singular: the flat triangle normal
          const Eigen::Vector3d a = m.fields.points.row(m.triangles(t, 0)), b = m.fields.points.row(m.triangles(t, 1)),
                                c = m.fields.points.row(m.triangles(t, 2));
          n = (b - a).cross(c - a);
        }
        n.normalize();
        const double diffuse = std::abs(n.dot(cam.view));
        if (o.mode == RenderMode::Zebra) {
          const double s = stripeParameter(n, cam.view, stripeDir, o.stripes.mode);
          const double base = stripeBlack(s, o.stripes) ? 0.06 : 0.97, light = 0.8 + 0.2 * diffuse;
          col[0] = col[1] = col[2] = base * light;
        } else if (o.mode == RenderMode::Curvature) {
          const auto c = r.scale.color(vw > 0 ? v / vw : std::numeric_limits<double>::quiet_NaN());
          const double light = 0.6 + 0.4 * diffuse;
          for (int i = 0; i < 3; ++i) col[i] = c[i] * light;
        } else {
          const double spec = std::pow(diffuse, 40.0);
          for (int i = 0; i < 3; ++i) col[i] = 0.72 * (0.25 + 0.75 * diffuse) + 0.25 * spec;
        }
      }
      float* a = &acc[3 * (static_cast<size_t>(y / ss) * (o.width - legendW) + x / ss)];
      for (int i = 0; i < 3; ++i) a[i] += static_cast<float>(col[i]);
    }
  });
  r.image = RasterImage(o.width, o.height);
  const float norm = 1.0f / static_cast<float>(ss * ss);
  for (int y = 0; y < o.height; ++y)
    for (int x = 0; x < o.width - legendW; ++x) {
      const float* a = &acc[3 * (static_cast<size_t>(y) * (o.width - legendW) + x)];
      r.image.set(x, y, toRgb8(a[0] * norm, a[1] * norm, a[2] * norm));
    }
  const int fs = std::max(1, o.height / 400);
  if (legend) drawLegend(r.image, r.scale, quantityTitle(o.quantity), o.width - legendW + 8 * fs);
  if (o.legend) {
    std::string caption;
    char buf[128];
    if (o.mode == RenderMode::Zebra) {
      std::snprintf(buf, sizeof buf, "%s, %d STRIPES", o.stripes.mode == StripeMode::Reflection ? "REFLECTION LINES" : "ISOPHOTES",
                    o.stripes.count);
      caption = buf;
    } else if (o.mode == RenderMode::Curvature) {
      caption = "RANGE " + tickLabel(r.valueMin) + " TO " + tickLabel(r.valueMax);
    }
    if (!caption.empty()) drawText(r.image, 6 * fs, o.height - 10 * fs, caption, fs, {20, 20, 20});
  }
  r.renderSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

RenderResult renderInspection(const TopoDS_Shape& shape, const RenderOptions& o) {
  // The image bounds the tessellation: past about two vertices per pixel the picture shows
  // nothing more, and a surface gone wrong would otherwise be refined for a minute.
  TessellationOptions to = o.tessellation;
  to.maxVertices = std::min(to.maxVertices, std::max<Eigen::Index>(100000, 2 * static_cast<Eigen::Index>(o.width) * o.height));
  const TessellationResult t = tessellateForInspection(shape, to);
  RenderResult r = renderInspection(t.mesh, o);
  r.maxInteriorNormalAngle = t.maxInteriorNormalAngle;
  r.maxBoundaryNormalAngle = t.maxBoundaryNormalAngle;
  r.warnings = t.warnings;
  r.refinementPasses = t.passes;
  r.tessellationSeconds = t.seconds;
  return r;
}

namespace {

std::vector<double> numberList(const std::string& key, const std::string& text, size_t count) {
  std::vector<double> v;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    try {
      size_t n = 0;
      v.push_back(std::stod(item, &n));
      if (n != item.size() || !std::isfinite(v.back())) throw 0;
    } catch (...) {
      v.clear();
      break;
    }
  }
  if (v.size() != count)
    throw Error(key + " needs " + std::to_string(count) + " comma-separated numbers, got '" + text + "'");
  return v;
}

double oneNumber(const std::string& key, const std::string& text) { return numberList(key, text, 1)[0]; }

bool flag(const std::string& key, const std::string& text) {
  if (text == "1" || text == "true" || text == "yes" || text == "True") return true;
  if (text == "0" || text == "false" || text == "no" || text == "False") return false;
  throw Error(key + " must be 0 or 1, got '" + text + "'");
}

}  // namespace

RenderOptions parseRenderOptions(const std::map<std::string, std::string>& in) {
  RenderOptions o;
  for (const auto& [key, v] : in) {
    if (key == "mode") o.mode = renderModeFromString(v);
    else if (key == "quantity") o.quantity = curvatureQuantityFromString(v);
    else if (key == "direction") { const auto d = numberList(key, v, 3); o.curvatureDirection = {d[0], d[1], d[2]}; }
    else if (key == "size") {
      int w = 0, h = 0;
      char x = 0, extra = 0;
      if (std::sscanf(v.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || (x != 'x' && x != 'X'))
        throw Error("size must be WxH, e.g. 1024x768, got '" + v + "'");
      o.width = w;
      o.height = h;
    } else if (key == "view") o.view = viewFromString(v);
    else if (key == "stripes") o.stripes.count = static_cast<int>(oneNumber(key, v));
    else if (key == "stripe-width") o.stripes.width = oneNumber(key, v);
    else if (key == "stripe-angle") o.stripes.angleDeg = oneNumber(key, v);
    else if (key == "stripe-mode") o.stripes.mode = stripeModeFromString(v);
    else if (key == "isophote-direction") {
      const auto d = numberList(key, v, 3);
      o.stripes.isophoteDirection = {d[0], d[1], d[2]};
      if (o.stripes.isophoteDirection.norm() == 0) throw Error("isophote-direction must not be zero");
    } else if (key == "scale-percentile") {
      const auto p = numberList(key, v, 2);
      o.scale.byValue = false;
      o.scale.lowPercentile = p[0];
      o.scale.highPercentile = p[1];
    } else if (key == "scale-range") {
      const auto p = numberList(key, v, 2);
      o.scale.byValue = true;
      o.scale.low = p[0];
      o.scale.high = p[1];
    } else if (key == "symmetric") {
      o.scale.symmetric = v == "auto" ? -1 : flag(key, v) ? 1 : 0;
    } else if (key == "faces") {
      for (double f : numberList(key, v, static_cast<size_t>(std::count(v.begin(), v.end(), ',') + 1)))
        o.tessellation.faces.push_back(static_cast<int>(f));
    } else if (key == "normal-angle") o.tessellation.maxNormalAngle = oneNumber(key, v) * M_PI / 180.0;
    else if (key == "edges") o.edges = flag(key, v);
    else if (key == "legend") o.legend = flag(key, v);
    else if (key == "supersample") o.supersample = static_cast<int>(oneNumber(key, v));
    else throw Error("unknown render option '" + key + "'");
  }
  return o;
}

std::string toJson(const RenderResult& r, const RenderOptions& o) {
  JsonWriter j;
  j.beginObject();
  j.field("mode", toString(o.mode)).field("width", r.image.width).field("height", r.image.height);
  if (o.mode == RenderMode::Curvature) {
    j.field("quantity", toString(o.quantity)).field("scale_low", r.scale.low).field("scale_high", r.scale.high);
    j.field("diverging", r.scale.diverging).field("value_min", r.valueMin).field("value_max", r.valueMax);
  }
  if (o.mode == RenderMode::Zebra) {
    j.field("stripe_mode", o.stripes.mode == StripeMode::Reflection ? "reflection" : "isophote");
    j.field("stripes", o.stripes.count).field("stripe_width", o.stripes.width);
  }
  j.field("vertices", static_cast<double>(r.vertices)).field("triangles", static_cast<double>(r.triangles));
  j.field("normal_angle_bound_deg", o.tessellation.maxNormalAngle * 180.0 / M_PI);
  j.field("max_interior_normal_angle_deg", r.maxInteriorNormalAngle * 180.0 / M_PI);
  j.field("max_boundary_normal_angle_deg", r.maxBoundaryNormalAngle * 180.0 / M_PI);
  j.field("refinement_passes", r.refinementPasses);
  j.field("tessellation_seconds", r.tessellationSeconds).field("render_seconds", r.renderSeconds);
  j.field("warnings", r.warnings);
  j.endObject();
  return j.str();
}

}  // namespace holefill

#include "mesh/mesh_io.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>
#include <vector>

#include "geometry/atomic_file.h"
#include "geometry/error.h"
#include "geometry/text_file.h"

namespace holefill {

namespace {

constexpr std::size_t kMaxFileBytes = std::size_t(4) << 30;  // 4 GiB: beyond any mesh we fill in memory

struct Builder {
  std::string name;
  std::vector<Eigen::Vector3d> points;
  std::vector<Eigen::Vector3i> triangles;

  [[noreturn]] void fail(const std::string& where, const std::string& what) const {
    throw Error("'" + name + "' is not a valid mesh file: " + where + ": " + what);
  }
  void addPoint(double x, double y, double z, const std::string& where) {
    if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z)) fail(where, "a coordinate is not finite (NaN or infinity)");
    points.emplace_back(x, y, z);
  }
  // A polygon as a fan; indices 0-based, checked against the points read so far or `limit`.
  void addPolygon(const std::vector<long long>& poly, long long limit, const std::string& where) {
    if (poly.size() < 3) fail(where, "a face needs at least 3 vertices");
    for (long long i : poly)
      if (i < 0 || i >= limit) fail(where, "vertex index " + std::to_string(i) + " is out of range (0.." + std::to_string(limit - 1) + ")");
    for (size_t k = 1; k + 1 < poly.size(); ++k) {
      const int a = int(poly[0]), b = int(poly[k]), c = int(poly[k + 1]);
      if (a == b || b == c || a == c) continue;  // a repeated corner adds no area: drop, like every reader does
      triangles.emplace_back(a, b, c);
    }
  }
  TriangleMesh finish() const {
    if (points.empty() || triangles.empty()) throw Error("'" + name + "' holds no triangles: the mesh is empty");
    TriangleMesh m;
    m.vertices.resize(static_cast<Eigen::Index>(points.size()), 3);
    for (size_t i = 0; i < points.size(); ++i) m.vertices.row(i) = points[i].transpose();
    m.triangles.resize(static_cast<Eigen::Index>(triangles.size()), 3);
    for (size_t i = 0; i < triangles.size(); ++i) m.triangles.row(i) = triangles[i].transpose();
    validateMesh(m, "'" + name + "'");
    return m;
  }
};

TriangleMesh parseObj(const std::string& bytes, Builder& b) {
  std::istringstream in(bytes);
  std::string line;
  int lineNo = 0;
  while (std::getline(in, line)) {
    ++lineNo;
    std::istringstream ls(line);
    std::string tag;
    if (!(ls >> tag)) continue;
    const std::string where = "line " + std::to_string(lineNo);
    if (tag == "v") {
      std::string t[3];
      double x[3];
      for (int k = 0; k < 3; ++k)
        if (!(ls >> t[k]) || !parseDouble(t[k], x[k])) b.fail(where, "a vertex needs three numbers");
      b.addPoint(x[0], x[1], x[2], where);
    } else if (tag == "f") {
      std::vector<long long> poly;
      std::string tok;
      while (ls >> tok) {
        long long i;
        if (!parseInt(tok.substr(0, tok.find('/')), i) || i == 0) b.fail(where, "bad face index '" + tok + "'");
        // OBJ is 1-based; negative indices count back from the last vertex read.
        poly.push_back(i > 0 ? i - 1 : static_cast<long long>(b.points.size()) + i);
      }
      b.addPolygon(poly, static_cast<long long>(b.points.size()), where);
    }
  }
  return b.finish();
}

// Tokens of an OFF/ASCII PLY body, skipping comments.
class Tokens {
public:
  explicit Tokens(const std::string& bytes) : in_(bytes) {}
  bool next(std::string& tok) {
    while (true) {
      if (ls_ >> tok) {
        if (tok[0] == '#') { ls_.setstate(std::ios::failbit); continue; }
        return true;
      }
      std::string line;
      if (!std::getline(in_, line)) return false;
      ++line_;
      ls_.clear();
      ls_.str(line);
    }
  }
  std::string where() const { return "line " + std::to_string(line_); }
  void skipLine() { ls_.setstate(std::ios::failbit); }

private:
  std::istringstream in_;
  std::istringstream ls_;
  int line_ = 0;
};

TriangleMesh parseOff(const std::string& bytes, Builder& b) {
  Tokens tk(bytes);
  std::string tok;
  if (!tk.next(tok) || (tok != "OFF" && tok.rfind("OFF", 0) != 0)) b.fail("line 1", "the file does not start with OFF");
  if (tok.size() > 3) b.fail("line 1", "only plain OFF is supported, not " + tok);
  long long nv, nf, ne;
  std::string t1, t2, t3;
  if (!tk.next(t1) || !tk.next(t2) || !tk.next(t3) || !parseInt(t1, nv) || !parseInt(t2, nf) || !parseInt(t3, ne) || nv < 0 ||
      nf < 0)
    b.fail(tk.where(), "the header needs vertex, face and edge counts");
  // Each vertex needs at least 6 bytes of text ("0 0 0\n"), each face 8: counts beyond that are lies.
  // Divided, not multiplied: a count near 2^63 would overflow (found by fuzzing, tests/fuzz).
  if (nv > static_cast<long long>(bytes.size()) / 6 || nf > static_cast<long long>(bytes.size()) / 8)
    b.fail(tk.where(), "the counts (" + std::to_string(nv) + " vertices, " + std::to_string(nf) +
                           " faces) do not fit in the file: it is truncated or corrupt");
  b.points.reserve(nv);
  for (long long i = 0; i < nv; ++i) {
    double x[3];
    for (int k = 0; k < 3; ++k)
      if (!tk.next(tok) || !parseDouble(tok, x[k])) b.fail(tk.where(), "vertex " + std::to_string(i) + " needs three numbers");
    b.addPoint(x[0], x[1], x[2], tk.where());
  }
  for (long long f = 0; f < nf; ++f) {
    long long k;
    if (!tk.next(tok) || !parseInt(tok, k) || k < 3 || k > 100000) b.fail(tk.where(), "face " + std::to_string(f) + " has no valid vertex count");
    std::vector<long long> poly(k);
    for (auto& i : poly)
      if (!tk.next(tok) || !parseInt(tok, i)) b.fail(tk.where(), "face " + std::to_string(f) + " is incomplete");
    // Colour values may follow the indices on the same line.
    tk.skipLine();
    b.addPolygon(poly, nv, tk.where());
  }
  // A body longer than its header says is a file whose header and data disagree: which of the
  // two is right cannot be told, so neither is trusted.
  if (tk.next(tok)) b.fail(tk.where(), "more data than the header's " + std::to_string(nv) + " vertices and " + std::to_string(nf) + " faces");
  return b.finish();
}

// ---- PLY ----
struct PlyProperty {
  std::string name, type, countType;  // countType set for lists
};
struct PlyElement {
  std::string name;
  long long count = 0;
  std::vector<PlyProperty> props;
};

int plySize(const std::string& t) {
  if (t == "char" || t == "uchar" || t == "int8" || t == "uint8") return 1;
  if (t == "short" || t == "ushort" || t == "int16" || t == "uint16") return 2;
  if (t == "int" || t == "uint" || t == "float" || t == "int32" || t == "uint32" || t == "float32") return 4;
  if (t == "double" || t == "float64") return 8;
  return 0;
}

double plyRead(const unsigned char* p, const std::string& t, bool bigEndian) {
  unsigned char buf[8];
  const int n = plySize(t);
  for (int i = 0; i < n; ++i) buf[i] = bigEndian ? p[n - 1 - i] : p[i];
  if (t == "char" || t == "int8") return static_cast<int8_t>(buf[0]);
  if (t == "uchar" || t == "uint8") return buf[0];
  if (t == "short" || t == "int16") { int16_t v; std::memcpy(&v, buf, 2); return v; }
  if (t == "ushort" || t == "uint16") { uint16_t v; std::memcpy(&v, buf, 2); return v; }
  if (t == "int" || t == "int32") { int32_t v; std::memcpy(&v, buf, 4); return v; }
  if (t == "uint" || t == "uint32") { uint32_t v; std::memcpy(&v, buf, 4); return v; }
  if (t == "float" || t == "float32") { float v; std::memcpy(&v, buf, 4); return v; }
  double v;
  std::memcpy(&v, buf, 8);
  return v;
}

TriangleMesh parsePly(const std::string& bytes, Builder& b) {
  if (bytes.compare(0, 3, "ply") != 0) b.fail("line 1", "the file does not start with ply");
  const auto headerEnd = bytes.find("end_header");
  if (headerEnd == std::string::npos) b.fail("header", "no end_header");
  std::istringstream header(bytes.substr(0, headerEnd));
  std::string line, format;
  std::vector<PlyElement> elements;
  while (std::getline(header, line)) {
    std::istringstream ls(line);
    std::string tag;
    ls >> tag;
    if (tag == "format") {
      ls >> format;
    } else if (tag == "element") {
      PlyElement e;
      ls >> e.name >> e.count;
      if (!ls || e.count < 0) b.fail("header", "bad element line '" + line + "'");
      elements.push_back(e);
    } else if (tag == "property") {
      if (elements.empty()) b.fail("header", "a property before any element");
      PlyProperty p;
      ls >> p.type;
      if (p.type == "list") ls >> p.countType >> p.type;
      ls >> p.name;
      if (!ls || plySize(p.type) == 0 || (!p.countType.empty() && plySize(p.countType) == 0))
        b.fail("header", "unsupported property '" + line + "'");
      elements.back().props.push_back(p);
    }
  }
  if (format != "ascii" && format != "binary_little_endian" && format != "binary_big_endian")
    b.fail("header", "unknown format '" + format + "'");
  size_t pos = bytes.find('\n', headerEnd);
  if (pos == std::string::npos) b.fail("header", "nothing after end_header");
  ++pos;
  const bool binary = format != "ascii";
  const bool big = format == "binary_big_endian";
  Tokens tk(binary ? std::string() : bytes.substr(pos));
  long long vertexCount = -1;
  for (const PlyElement& e : elements) {
    const bool isVertex = e.name == "vertex", isFace = e.name == "face";
    if (isVertex) vertexCount = e.count;
    // Every element takes at least one byte per property: a larger count is a lie.
    if (e.count > static_cast<long long>(bytes.size())) b.fail("header", "element '" + e.name + "' count exceeds the file size");
    for (long long i = 0; i < e.count; ++i) {
      double xyz[3] = {NAN, NAN, NAN};
      std::vector<long long> poly;
      for (const PlyProperty& p : e.props) {
        auto value = [&](const std::string& type) -> double {
          if (!binary) {
            std::string tok;
            double v;
            if (!tk.next(tok) || !parseDouble(tok, v)) b.fail(e.name + " " + std::to_string(i), "missing or bad value");
            return v;
          }
          const int n = plySize(type);
          if (pos + n > bytes.size()) b.fail(e.name + " " + std::to_string(i), "the file is truncated");
          const double v = plyRead(reinterpret_cast<const unsigned char*>(bytes.data()) + pos, type, big);
          pos += n;
          return v;
        };
        if (!p.countType.empty()) {
          const double k = value(p.countType);
          if (!(k >= 0 && k <= 100000)) b.fail(e.name + " " + std::to_string(i), "bad list length");
          const bool indices = isFace && (p.name == "vertex_indices" || p.name == "vertex_index");
          std::vector<long long> list;
          for (size_t j = 0; j < static_cast<size_t>(k); ++j) {
            const double x = value(p.type);
            if (!indices) continue;  // other lists (texture coordinates, ...) are read past
            // A float list or a huge value is no vertex index; converting it would be undefined (fuzzing).
            if (!(std::abs(x) < 9e18) || x != std::floor(x))
              b.fail(e.name + " " + std::to_string(i), "a vertex index that is not an integer");
            list.push_back(static_cast<long long>(x));
          }
          if (indices) poly = list;
        } else {
          const double v = value(p.type);
          if (isVertex && p.name.size() == 1 && p.name[0] >= 'x' && p.name[0] <= 'z') xyz[p.name[0] - 'x'] = v;
        }
      }
      if (isVertex) b.addPoint(xyz[0], xyz[1], xyz[2], "vertex " + std::to_string(i));
      if (isFace) {
        if (vertexCount < 0) b.fail("header", "faces come before vertices");
        b.addPolygon(poly, vertexCount, "face " + std::to_string(i));
      }
    }
  }
  // Data past the declared elements: the header and the body disagree (see parseOff).
  std::string extra;
  const bool more = binary ? bytes.find_first_not_of(" \t\r\n", pos) != std::string::npos : tk.next(extra);
  if (more) b.fail(binary ? "body" : tk.where(), "more data than the header declares (its element counts disagree with the body)");
  return b.finish();
}

// ---- STL ----
struct PointKey {
  double x, y, z;
  bool operator<(const PointKey& o) const { return std::tie(x, y, z) < std::tie(o.x, o.y, o.z); }
};

TriangleMesh parseStl(const std::string& bytes, Builder& b) {
  std::map<PointKey, int> index;
  auto corner = [&](double x, double y, double z, const std::string& where) {
    if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z)) b.fail(where, "a coordinate is not finite (NaN or infinity)");
    auto [it, inserted] = index.emplace(PointKey{x, y, z}, static_cast<int>(b.points.size()));
    if (inserted) b.points.emplace_back(x, y, z);
    return static_cast<long long>(it->second);
  };
  // A binary STL's size is exactly 84 + 50·n; ASCII files may also start with "solid", so decide by size.
  uint32_t n = 0;
  if (bytes.size() >= 84) std::memcpy(&n, bytes.data() + 80, 4);
  if (bytes.size() >= 84 && bytes.size() == 84 + 50 * static_cast<size_t>(n)) {
    for (uint32_t t = 0; t < n; ++t) {
      const char* p = bytes.data() + 84 + 50 * static_cast<size_t>(t) + 12;
      std::vector<long long> poly;
      for (int k = 0; k < 3; ++k) {
        float c[3];
        std::memcpy(c, p + 12 * k, 12);
        poly.push_back(corner(c[0], c[1], c[2], "triangle " + std::to_string(t)));
      }
      b.addPolygon(poly, static_cast<long long>(b.points.size()), "triangle " + std::to_string(t));
    }
    return b.finish();
  }
  if (bytes.compare(0, 5, "solid") != 0) b.fail("header", "neither ASCII STL (\"solid\") nor a binary STL of consistent size");
  std::istringstream in(bytes);
  std::string tok;
  std::vector<long long> poly;
  long long facet = 0;
  while (in >> tok) {
    if (tok == "vertex") {
      std::string t[3];
      double x[3];
      for (int k = 0; k < 3; ++k)
        if (!(in >> t[k]) || !parseDouble(t[k], x[k])) b.fail("facet " + std::to_string(facet), "a vertex needs three numbers");
      poly.push_back(corner(x[0], x[1], x[2], "facet " + std::to_string(facet)));
    } else if (tok == "endfacet") {
      b.addPolygon(poly, static_cast<long long>(b.points.size()), "facet " + std::to_string(facet));
      poly.clear();
      ++facet;
    }
  }
  return b.finish();
}

}  // namespace

TriangleMesh parseMesh(const std::string& bytes, const std::string& extension, const std::string& name) {
  Builder b;
  b.name = name;
  const std::string ext = lowerCase(extension);
  if (bytes.empty()) throw Error("'" + name + "' is empty");
  if (ext == "obj") return parseObj(bytes, b);
  if (ext == "off") return parseOff(bytes, b);
  if (ext == "ply") return parsePly(bytes, b);
  if (ext == "stl") return parseStl(bytes, b);
  throw Error("unsupported mesh type '." + ext + "' of '" + name + "': use .obj, .off, .ply or .stl");
}

TriangleMesh readMesh(const std::string& path) {
  const std::string ext = fileExtension(path);
  if (ext != "obj" && ext != "off" && ext != "ply" && ext != "stl")
    throw Error("unsupported mesh type '." + ext + "' of '" + path + "': use .obj, .off, .ply or .stl");
  const std::string bytes = readFileBytes(path, kMaxFileBytes);
  return parseMesh(bytes, ext, path);
}

std::string formatMesh(const TriangleMesh& mesh, const std::string& extension) {
  const std::string ext = lowerCase(extension);
  std::ostringstream out;
  out << std::setprecision(17);
  const Eigen::Index nv = mesh.vertices.rows(), nt = mesh.triangles.rows();
  if (ext == "obj") {
    for (Eigen::Index i = 0; i < nv; ++i) out << "v " << mesh.vertices(i, 0) << ' ' << mesh.vertices(i, 1) << ' ' << mesh.vertices(i, 2) << '\n';
    for (Eigen::Index t = 0; t < nt; ++t)
      out << "f " << mesh.triangles(t, 0) + 1 << ' ' << mesh.triangles(t, 1) + 1 << ' ' << mesh.triangles(t, 2) + 1 << '\n';
  } else if (ext == "off" || ext == "ply") {
    if (ext == "off") {
      out << "OFF\n" << nv << ' ' << nt << " 0\n";
    } else {
      out << "ply\nformat ascii 1.0\nelement vertex " << nv << "\nproperty double x\nproperty double y\nproperty double z\n"
          << "element face " << nt << "\nproperty list uchar int vertex_indices\nend_header\n";
    }
    for (Eigen::Index i = 0; i < nv; ++i) out << mesh.vertices(i, 0) << ' ' << mesh.vertices(i, 1) << ' ' << mesh.vertices(i, 2) << '\n';
    for (Eigen::Index t = 0; t < nt; ++t) out << "3 " << mesh.triangles(t, 0) << ' ' << mesh.triangles(t, 1) << ' ' << mesh.triangles(t, 2) << '\n';
  } else if (ext == "stl") {
    std::string bytes(84 + 50 * static_cast<size_t>(nt), '\0');
    const std::string title = "binary STL written by HoleFill";
    std::memcpy(bytes.data(), title.data(), title.size());
    const uint32_t n = static_cast<uint32_t>(nt);
    std::memcpy(bytes.data() + 80, &n, 4);
    for (Eigen::Index t = 0; t < nt; ++t) {
      float f[12];
      Eigen::Vector3d p[3];
      for (int k = 0; k < 3; ++k) p[k] = mesh.vertices.row(mesh.triangles(t, k)).transpose();
      Eigen::Vector3d nrm = (p[1] - p[0]).cross(p[2] - p[0]);
      if (nrm.norm() > 0) nrm.normalize();
      for (int k = 0; k < 3; ++k) f[k] = static_cast<float>(nrm[k]);
      for (int c = 0; c < 3; ++c)
        for (int k = 0; k < 3; ++k) f[3 + 3 * c + k] = static_cast<float>(p[c][k]);
      std::memcpy(bytes.data() + 84 + 50 * t, f, 48);
    }
    return bytes;
  } else {
    throw Error("unsupported mesh type '." + ext + "': use .obj, .off, .ply or .stl");
  }
  return out.str();
}

void writeMesh(const TriangleMesh& mesh, const std::string& path) {
  writeFileAtomically(path, formatMesh(mesh, fileExtension(path)));
}

}  // namespace holefill

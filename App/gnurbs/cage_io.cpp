#include "gnurbs/cage_io.h"

#include <cmath>
#include <iomanip>
#include <sstream>
#include <vector>

#include "geometry/error.h"
#include "geometry/tolerances.h"
#include "geometry/text_file.h"

namespace holefill {

namespace {

constexpr std::size_t kMaxCageBytes = std::size_t(1) << 30;

[[noreturn]] void fail(const std::string& name, const std::string& where, const std::string& what) {
  throw Error("'" + name + "' is not a valid quad cage: " + where + ": " + what);
}

// A 1-based vertex index token (OBJ's a/t/n form allowed) as 0-based.
int vertexIndex(const std::string& tok, const std::string& name, const std::string& where) {
  long long i = 0;
  if (!parseInt(tok.substr(0, tok.find('/')), i) || i < 1 || i > (1LL << 31) - 1)
    fail(name, where, "bad vertex index '" + tok + "' (1-based)");
  return static_cast<int>(i - 1);
}

double finiteNumber(const std::string& tok, const std::string& name, const std::string& where) {
  double x = 0;
  if (!parseDouble(tok, x)) fail(name, where, "'" + tok + "' is not a number");
  if (!std::isfinite(x)) fail(name, where, "a number is not finite (NaN or infinity)");
  return x;
}

// A coordinate: finite and within tol::kMaxCoordinate (the patches' poles are sums of products of
// the cage's coordinates; at 1e50 they overflowed to infinities and OCCT crashed on them, at
// 1e150 the shell came out invalid and was written).
double coordinate(const std::string& tok, const std::string& name, const std::string& where) {
  const double x = finiteNumber(tok, name, where);
  if (std::abs(x) > tol::kMaxCoordinate)
    fail(name, where, "a coordinate beyond " + std::to_string(static_cast<long long>(tol::kMaxCoordinate)) + " (corrupt, or in the wrong units)");
  return x;
}

// A JSON array of arrays of numbers, each inner array of `width` entries.
std::vector<std::vector<double>> numberRows(const std::string& text, size_t width, const std::string& name) {
  std::vector<std::vector<double>> rows;
  size_t i = 0;
  auto skip = [&] {
    while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
  };
  auto expect = [&](char c) {
    skip();
    if (i >= text.size() || text[i] != c)
      throw Error("'" + name + "' is not a JSON list of [" + std::to_string(width) + " numbers] lists: expected '" + c + "' at character " +
                  std::to_string(i + 1));
    ++i;
  };
  expect('[');
  skip();
  if (i < text.size() && text[i] == ']') return rows;
  while (true) {
    expect('[');
    std::vector<double> row;
    while (true) {
      skip();
      const size_t start = i;
      while (i < text.size() && (std::isalnum(static_cast<unsigned char>(text[i])) || text[i] == '.' || text[i] == '-' || text[i] == '+')) ++i;
      row.push_back(finiteNumber(text.substr(start, i - start), name, "entry " + std::to_string(rows.size() + 1)));
      skip();
      if (i < text.size() && text[i] == ',') { ++i; continue; }
      expect(']');
      break;
    }
    if (row.size() != width)
      throw Error("'" + name + "': entry " + std::to_string(rows.size() + 1) + " has " + std::to_string(row.size()) + " numbers, expected " +
                  std::to_string(width));
    rows.push_back(row);
    skip();
    if (i < text.size() && text[i] == ',') { ++i; continue; }
    expect(']');
    break;
  }
  skip();
  if (i != text.size()) throw Error("'" + name + "': unexpected text after the list at character " + std::to_string(i + 1));
  return rows;
}

int oneBased(double x, const std::string& name, size_t entry) {
  if (x != std::floor(x) || x < 1 || x > 2147483647.0)
    throw Error("'" + name + "': entry " + std::to_string(entry) + " names vertex " + std::to_string(x) + "; vertex numbers are 1-based integers");
  return static_cast<int>(x) - 1;
}

}  // namespace

QuadCage parseCageObj(const std::string& bytes, const std::string& name) {
  if (bytes.empty()) throw Error("'" + name + "' is empty");
  std::vector<Eigen::RowVector3d> points;
  std::vector<Eigen::RowVector4i> quads;
  std::vector<int> quadLine;
  QuadCage cage;
  cage.numberBase = 1;
  std::istringstream in(bytes);
  std::string line;
  for (int lineNo = 1; std::getline(in, line); ++lineNo) {
    std::istringstream ls(line);
    std::string tag;
    if (!(ls >> tag)) continue;
    const std::string where = "line " + std::to_string(lineNo);
    std::vector<std::string> t;
    for (std::string tok; ls >> tok;) t.push_back(tok);
    if (tag == "v") {
      if (t.size() < 3) fail(name, where, "a vertex needs three numbers");
      points.emplace_back(coordinate(t[0], name, where), coordinate(t[1], name, where), coordinate(t[2], name, where));
    } else if (tag == "f") {
      if (t.size() != 4)
        fail(name, where, "a face with " + std::to_string(t.size()) + " corners; a G-NURBS cage must be all quads (subdivide other faces first)");
      Eigen::RowVector4i q;
      for (int k = 0; k < 4; ++k) q[k] = vertexIndex(t[k], name, where);
      quads.push_back(q);
      quadLine.push_back(lineNo);
    } else if (tag == "#" && !t.empty()) {
      const std::string kind = t[0];
      if (kind == "sharp") {
        if (t.size() != 3) fail(name, where, "use '# sharp i j' (1-based vertex numbers)");
        cage.setSharp(vertexIndex(t[1], name, where), vertexIndex(t[2], name, where));
      } else if (kind == "knot") {
        if (t.size() != 4) fail(name, where, "use '# knot i j d' (1-based vertex numbers, interval d > 0)");
        cage.setKnot(vertexIndex(t[1], name, where), vertexIndex(t[2], name, where), finiteNumber(t[3], name, where));
      } else if (kind == "anchor") {
        if (t.size() != 5) fail(name, where, "use '# anchor i x y z' (1-based vertex number)");
        cage.anchors[vertexIndex(t[1], name, where)] =
            Eigen::Vector3d(coordinate(t[2], name, where), coordinate(t[3], name, where), coordinate(t[4], name, where));
      }
    }
  }
  if (quads.empty()) throw Error("'" + name + "' holds no faces: the cage is empty");
  for (size_t f = 0; f < quads.size(); ++f)
    for (int k = 0; k < 4; ++k)
      if (quads[f][k] >= static_cast<int>(points.size()))
        fail(name, "line " + std::to_string(quadLine[f]),
             "vertex " + std::to_string(quads[f][k] + 1) + " does not exist (the file has " + std::to_string(points.size()) + ")");
  cage.vertices.resize(static_cast<Eigen::Index>(points.size()), 3);
  for (size_t i = 0; i < points.size(); ++i) cage.vertices.row(static_cast<Eigen::Index>(i)) = points[i];
  cage.quads.resize(static_cast<Eigen::Index>(quads.size()), 4);
  for (size_t i = 0; i < quads.size(); ++i) cage.quads.row(static_cast<Eigen::Index>(i)) = quads[i];
  try {
    CageTopology check(cage);
  } catch (const Error& e) {
    throw Error("'" + name + "': " + e.what());
  }
  return cage;
}

QuadCage readCage(const std::string& path) {
  if (fileExtension(path) != "obj") throw Error("unsupported cage file '" + path + "': use an .obj of quads");
  return parseCageObj(readFileBytes(path, kMaxCageBytes), path);
}

std::string formatCageObj(const QuadCage& cage) {
  std::ostringstream out;
  out << std::setprecision(17);
  for (Eigen::Index i = 0; i < cage.vertices.rows(); ++i)
    out << "v " << cage.vertices(i, 0) << ' ' << cage.vertices(i, 1) << ' ' << cage.vertices(i, 2) << '\n';
  for (Eigen::Index f = 0; f < cage.quads.rows(); ++f)
    out << "f " << cage.quads(f, 0) + 1 << ' ' << cage.quads(f, 1) + 1 << ' ' << cage.quads(f, 2) + 1 << ' ' << cage.quads(f, 3) + 1 << '\n';
  auto ends = [](std::uint64_t key) { return std::to_string((key & 0xffffffffu) + 1) + " " + std::to_string((key >> 32) + 1); };
  for (std::uint64_t key : cage.sharp) out << "# sharp " << ends(key) << '\n';
  for (const auto& [key, d] : cage.knots) out << "# knot " << ends(key) << ' ' << d << '\n';
  for (const auto& [v, a] : cage.anchors) out << "# anchor " << v + 1 << ' ' << a.x() << ' ' << a.y() << ' ' << a.z() << '\n';
  return out.str();
}

void addSharpEdgesFromJson(QuadCage& cage, const std::string& text, const std::string& name) {
  const auto rows = numberRows(text, 2, name);
  QuadCage c = cage;  // the caller's cage stays as it was when the list is refused
  for (size_t r = 0; r < rows.size(); ++r) c.setSharp(oneBased(rows[r][0], name, r + 1), oneBased(rows[r][1], name, r + 1));
  CageTopology check(c);
  cage = std::move(c);
}

void addAnchorsFromJson(QuadCage& cage, const std::string& text, const std::string& name) {
  const auto rows = numberRows(text, 4, name);
  QuadCage c = cage;
  for (size_t r = 0; r < rows.size(); ++r) {
    // (Coordinates past tol::kMaxCoordinate: CageTopology below refuses them, naming the vertex.)
    c.anchors[oneBased(rows[r][0], name, r + 1)] = Eigen::Vector3d(rows[r][1], rows[r][2], rows[r][3]);
  }
  CageTopology check(c);
  cage = std::move(c);
}

}  // namespace holefill

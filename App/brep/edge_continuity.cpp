#include "brep/edge_continuity.h"

#include <BRep_Tool.hxx>
#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

#include "brep/boundary_sampling.h"
#include "geometry/error.h"
#include "geometry/tolerances.h"

namespace holefill {

namespace {

// Support normal of a loop edge at its start (atEnd = false) or end along the loop's traversal.
bool endNormal(const HoleEdge& he, bool atEnd, Eigen::Vector3d& n) {
  double first = 0, last = 0;
  BRep_Tool::Range(he.edge, first, last);
  const bool reversed = he.edge.Orientation() == TopAbs_REVERSED;
  return supportNormal(he.edge, he.support, atEnd != reversed ? last : first, n);
}

}  // namespace

std::vector<double> cornerMismatch(const Hole& hole) {
  const size_t m = hole.edges.size();
  std::vector<double> r(m, -1.0);
  for (size_t i = 0; i < m; ++i) {
    // The vertex between edge a = i-1 (arriving) and b = i (leaving).
    const HoleEdge& a = hole.edges[(i + m - 1) % m];
    const HoleEdge& b = hole.edges[i];
    if (!b.cornerAtStart || m < 2) continue;
    const Eigen::Vector3d nc = edgeTangent(a.edge, true).cross(edgeTangent(b.edge, false));
    // A cusp (turn near 180 deg) leaves the tangent plane as undetermined as a smooth vertex.
    if (nc.norm() < std::sin(tol::kCornerAngleDeg * M_PI / 180.0)) continue;
    const Eigen::Vector3d ncu = nc.normalized();
    Eigen::Vector3d n;
    if (endNormal(a, true, n))
      r[(i + m - 1) % m] = std::max(r[(i + m - 1) % m], std::acos(std::min(1.0, std::abs(n.dot(ncu)))));
    if (endNormal(b, false, n)) r[i] = std::max(r[i], std::acos(std::min(1.0, std::abs(n.dot(ncu)))));
  }
  return r;
}

std::vector<EdgeRequest> edgeRequests(const Hole& hole, Continuity requested, const std::map<int, Continuity>& overrides,
                                      const EdgeContinuityOptions& opt) {
  std::set<int> onLoop;
  for (const auto& e : hole.edges) onLoop.insert(e.edgeIndex);
  for (const auto& [edge, c] : overrides)
    if (!onLoop.count(edge))
      throw Error("edge continuity names Edge" + std::to_string(edge) + ", which is not on the hole's loop");
  const std::vector<double> mismatch = opt.detectCreases ? cornerMismatch(hole) : std::vector<double>(hole.edges.size(), -1.0);
  std::vector<EdgeRequest> r;
  for (size_t i = 0; i < hole.edges.size(); ++i) {
    EdgeRequest q;
    q.edgeIndex = hole.edges[i].edgeIndex;
    q.cornerMismatch = mismatch[i];
    q.asked = requested;
    q.source = "request";
    if (auto it = overrides.find(q.edgeIndex); it != overrides.end()) {
      q.asked = std::min(it->second, requested, [](Continuity x, Continuity y) { return int(x) < int(y); });
      q.source = "override";
    } else if (requested > Continuity::G0 && mismatch[i] > opt.creaseAngle) {
      q.asked = Continuity::G0;
      q.source = "crease";
    }
    r.push_back(q);
  }
  return r;
}

std::map<int, Continuity> parseEdgeContinuity(const std::string& spec) {
  std::map<int, Continuity> r;
  std::stringstream ss(spec);
  std::string item;
  while (std::getline(ss, item, ',')) {
    if (item.empty()) continue;
    const size_t eq = item.find('=');
    if (eq == std::string::npos) throw Error("edge continuity '" + item + "': write Edge5=G0");
    std::string name = item.substr(0, eq);
    if (name.rfind("Edge", 0) == 0) name = name.substr(4);
    if (name.empty() || name.find_first_not_of("0123456789") != std::string::npos || std::stoll(name) < 1 ||
        std::stoll(name) > 100000000)
      throw Error("edge continuity '" + item + "': '" + item.substr(0, eq) + "' is not an edge name like Edge5");
    r[std::stoi(name)] = continuityFromString(item.substr(eq + 1));
  }
  if (r.empty()) throw Error("edge continuity names no edge: write Edge5=G0,Edge7=G2");
  return r;
}

}  // namespace holefill

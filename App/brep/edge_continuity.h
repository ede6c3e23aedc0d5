// Per-edge continuity of a hole (issue 20): which continuity each loop edge can be asked for.
// A fill meets its support at edge e only as well as the original model met it there, and a
// loop often mixes both: a fillet is tangent to its two walls and sharp against its end caps.
// The loop itself tells which: at a corner vertex, where edges a and b meet at a tangent break,
// any face bounded by the loop has the tangent plane spanned by t_a and t_b, so its normal there
// is n_c = t_a x t_b. A G1 fill along a is then only possible when a's support normal at that
// vertex is parallel to n_c; where it is not (by more than creaseAngle), the original face was
// sharp along a and G1 cannot be met, so a is a crease and gets G0. On the corpus's real holes
// this mismatch equals the removed face's own measured G1 at that edge to two digits. Vertices without a tangent
// break say nothing (n_c is undetermined there); an edge with no corner at either end keeps the
// requested continuity. Explicit per-edge requests override the detection (lowering or raising
// up to the requested maximum).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "brep/hole_detection.h"
#include "fill/variational_fill.h"
#include "geometry/tolerances.h"

namespace holefill {

struct EdgeContinuityOptions {
  bool detectCreases = true;   // creases found at the loop's corners get G0
  // Support normal vs the corner normal t_a x t_b (radians). DESIGN's loose G1 tier (1e-2): past it
  // no fill can be G1 at that corner even loosely, and the corpus counts such an edge a crease.
  double creaseAngle = tol::kG1Loose;
};

struct EdgeRequest {
  int edgeIndex = 0;              // 1-based model edge (FreeCAD Edge<k>)
  Continuity asked = Continuity::G1;
  std::string source;             // "request", "crease" (detected) or "override" (explicit)
  double cornerMismatch = -1.0;   // max angle(support normal, ±n_c) at the edge's corners (rad); -1: no corner
};

// Angle between edge i's support normal and the corner normal at each corner end of edge i,
// the larger of the two; -1 when neither end is a corner where n_c is defined.
std::vector<double> cornerMismatch(const Hole& hole);

// The continuity asked of each loop edge, in loop order. `requested` is the maximum; `overrides`
// maps 1-based model edge indices to explicit requests (an index not on the loop throws).
std::vector<EdgeRequest> edgeRequests(const Hole& hole, Continuity requested, const std::map<int, Continuity>& overrides,
                                      const EdgeContinuityOptions& options = {});

// "Edge5=G0,Edge7=G2" (or "5=G0,7=G2") -> {5: G0, 7: G2}; throws on a malformed entry.
std::map<int, Continuity> parseEdgeContinuity(const std::string& spec);

}  // namespace holefill

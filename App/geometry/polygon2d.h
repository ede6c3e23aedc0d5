// Closed planar polygons as they occur in parameter domains: signed area
// (orientation), point containment, a self-intersection test (a pcurve that
// folds cannot trim a face), and mean value coordinates (Floater 2003,
// "Mean value coordinates", CAGD 20:19-27), which interpolate boundary data
// into a polygon's interior for any simple polygon, convex or not.
#pragma once

#include <Eigen/Dense>
#include <cstdint>
#include <utility>
#include <vector>

namespace holefill {

using Polygon2 = std::vector<Eigen::Vector2d>;  // closed implicitly (last vertex connects to first)

double signedArea(const Polygon2& poly);  // > 0 for counter-clockwise
// Distance from q to the segment a–b (to a where the segment has no length).
double segmentDistance(const Eigen::Vector2d& q, const Eigen::Vector2d& a, const Eigen::Vector2d& b);
bool contains(const Polygon2& poly, const Eigen::Vector2d& x);  // even-odd rule
// An edge of one of several loops: edge k runs from vertex k to vertex k + 1 (the last closes it).
struct LoopEdge {
  size_t loop = 0, edge = 0;
};
// The pairs of edges that cross properly (their interiors meet at one point), within a loop and
// between loops, up to `limit` pairs; edges that only touch, zero-length edges and adjacent
// edges do not count, unless `touch` ≥ 0: then edges within `touch` of each other count too
// (a vertex on another edge, collinear edges overlapping). A sweep over the edges' x extents:
// loops of tens of thousands of edges (a large hole's boundary) are checked in about n log n.
std::vector<std::pair<LoopEdge, LoopEdge>> crossingEdges(const std::vector<Polygon2>& loops, size_t limit = SIZE_MAX, double touch = -1);
// True when two edges of the polygon cross.
bool selfIntersects(const Polygon2& poly);
// The loop with no two edges within `touch` of each other: where two meet (cross, or touch, as a
// loop running back along a stretch of itself does) the smaller of the two loops they split it
// into, by area, is cut off, the larger kept in order. A map folded at its boundary leaves such
// contacts, which BRepCheck calls a self-intersecting wire; what is cut off is the fold.
Polygon2 withoutSelfContacts(Polygon2 loop, double touch);
// True when an edge of one polygon crosses an edge of the other.
bool loopsCross(const Polygon2& p, const Polygon2& q);
// The angle (radians, in [0, π/2)) by which the points, turned anticlockwise about the origin,
// have the least-area axis-aligned bounding rectangle. The least rectangle has a side along an
// edge of the convex hull (Freeman & Shapira 1975), so each hull edge is tried. 0 for fewer than
// three points or points on one line.
double leastAreaRectangleAngle(const std::vector<Eigen::Vector2d>& points);
// Mean value coordinates of x (strictly inside) w.r.t. the polygon vertices; they sum to 1.
Eigen::VectorXd meanValueCoordinates(const Polygon2& poly, const Eigen::Vector2d& x);

}  // namespace holefill

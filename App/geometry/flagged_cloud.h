// The point-cloud text format of `holefill param` / `fit-points` (bidgcn.md's data): one point per
// line, "x y z flag u v", flag 1 for a boundary point whose parameters u v are given, 0 for an
// interior point (its u v ignored, and they may be left out); boundary points may all leave
// their u v out too (then they are to be computed). A cloud of bare "x y z" lines has no flags:
// its boundary is to be found (cloud_boundary.h). Blank lines and lines starting with '#' are
// skipped. Parsed from text, so the core reads it without files.
#pragma once

#include <Eigen/Dense>
#include <string>
#include <vector>

namespace holefill {

struct FlaggedCloud {
  Eigen::MatrixX3d points;
  std::vector<bool> boundary;
  Eigen::MatrixX2d uv;  // given for boundary points, 0 elsewhere
  bool boundaryUVGiven = true;  // false: no boundary point carries u v
  bool flagsGiven = true;       // false: bare x y z lines, no point is marked
};

// Throws Error naming the line for anything else (missing columns, flags on some lines only, a flag other than 0/1,
// non-finite numbers, boundary points with and without u v mixed) and for a text without points.
FlaggedCloud parseFlaggedCloud(const std::string& text, const std::string& name = "cloud");

}  // namespace holefill

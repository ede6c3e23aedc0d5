#include "geometry/flagged_cloud.h"

#include <cmath>
#include <sstream>

#include "geometry/error.h"
#include "geometry/text_file.h"

namespace holefill {

FlaggedCloud parseFlaggedCloud(const std::string& text, const std::string& name) {
  std::istringstream in(text);
  std::vector<Eigen::RowVector3d> pts;
  std::vector<Eigen::RowVector2d> uvs;
  std::vector<bool> flags;
  int withUV = -1;  // whether boundary points carry u v: unknown until the first one
  int bare = -1;    // whether lines are bare x y z: unknown until the first one
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    std::istringstream ls(line);
    std::vector<std::string> t;
    for (std::string w; ls >> w;) t.push_back(w);
    if (t.empty() || t[0][0] == '#') continue;
    const std::string where = "'" + name + "' line " + std::to_string(n);
    if (t.size() != 3 && t.size() != 4 && t.size() != 6) throw Error(where + ": expected x y z [flag [u v]], got " + std::to_string(t.size()) + " columns");
    if (bare < 0) bare = t.size() == 3;
    if (bare != (t.size() == 3)) throw Error(where + ": give the flag on every line or on none");
    double x[6] = {0, 0, 0, 0, 0, 0};
    for (size_t k = 0; k < t.size(); ++k)
      if (!parseDouble(t[k], x[k]) || !std::isfinite(x[k])) throw Error(where + ": '" + t[k] + "' is not a finite number");
    if (x[3] != 0 && x[3] != 1) throw Error(where + ": the flag must be 0 (interior) or 1 (boundary with u v)");
    if (x[3] == 1) {
      const int given = t.size() == 6 ? 1 : 0;
      if (withUV < 0) withUV = given;
      if (withUV != given) throw Error(where + ": give u v for every boundary point (flag 1) or for none");
    }
    pts.emplace_back(x[0], x[1], x[2]);
    flags.push_back(x[3] == 1);
    uvs.emplace_back(x[3] == 1 && t.size() == 6 ? x[4] : 0, x[3] == 1 && t.size() == 6 ? x[5] : 0);
  }
  if (pts.empty()) throw Error("'" + name + "' holds no points");
  FlaggedCloud c;
  c.points.resize(static_cast<Eigen::Index>(pts.size()), 3);
  c.uv.resize(static_cast<Eigen::Index>(pts.size()), 2);
  for (size_t k = 0; k < pts.size(); ++k) c.points.row(static_cast<Eigen::Index>(k)) = pts[k], c.uv.row(static_cast<Eigen::Index>(k)) = uvs[k];
  c.boundary = flags;
  c.boundaryUVGiven = withUV != 0 && bare == 0;
  c.flagsGiven = bare == 0;
  return c;
}

}  // namespace holefill

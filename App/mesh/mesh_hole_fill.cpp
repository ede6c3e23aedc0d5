#include "mesh/mesh_hole_fill.h"

#include <algorithm>
#include <set>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <unordered_map>
#include <unordered_set>

#include "geometry/error.h"
#include "geometry/json_writer.h"
#include "mesh/mesh_topology.h"
#include "mesh/self_intersection.h"

namespace holefill {

namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

MeshFillResult fillMeshHoles(const TriangleMesh& input, const MeshFillOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  if (input.triangles.rows() == 0) throw Error("the mesh has no triangles; there is nothing to fill");
  if (!(options.weld >= 0) || !std::isfinite(options.weld)) throw Error("weld: a fraction of the diagonal, 0 or more");
  MeshFillResult result;
  validateMesh(input);
  VertexWeld welded;
  if (options.weld > 0) {
    welded = weldVertices(input, options.weld * boundingDiagonal(input.vertices));
    result.weldedVertices = welded.mergedVertices;
    result.droppedTriangles = welded.droppedTriangles;
    if (welded.mesh.triangles.rows() == 0) throw Error("weld: the merge collapsed every triangle; use a smaller weld tolerance");
  }
  const TriangleMesh& mesh = options.weld > 0 ? welded.mesh : input;
  const MeshTopology topo(mesh);
  result.detection = findMeshHoles(mesh, topo);
  const MeshHoleReport& detection = result.detection;
  result.warnings = detection.warnings;

  std::vector<bool> wanted(detection.holes.size(), options.holes.empty());
  for (int h : options.holes) {
    if (h < 0 || h >= static_cast<int>(detection.holes.size()))
      throw Error("hole " + std::to_string(h) + " does not exist; the mesh has " + std::to_string(detection.holes.size()) +
                  " holes (0-based)");
    wanted[h] = true;
  }

  // Per vertex: area-weighted normal sum and mean edge length, both in the surrounding mesh.
  const Eigen::Index nv = mesh.vertices.rows();
  std::vector<Eigen::Vector3d> normalSum(nv, Eigen::Vector3d::Zero());
  std::vector<double> edgeSum(nv, 0);
  std::vector<int> edgeCount(nv, 0);
  auto point = [&](int v) { return Eigen::Vector3d(mesh.vertices.row(v).transpose()); };
  auto orientedNormal = [&](int t) {
    const int a = mesh.triangles(t, 0), b = topo.nextVertex(t, a), c = topo.nextVertex(t, b);
    return Eigen::Vector3d((point(b) - point(a)).cross(point(c) - point(a)));
  };
  for (Eigen::Index t = 0; t < mesh.triangles.rows(); ++t) {
    const Eigen::Vector3d n = orientedNormal(static_cast<int>(t));
    for (int k = 0; k < 3; ++k) normalSum[mesh.triangles(t, k)] += n;
  }
  for (const MeshTopology::Edge& e : topo.edges()) {
    const double len = (point(e.a) - point(e.b)).norm();
    edgeSum[e.a] += len; edgeSum[e.b] += len;
    ++edgeCount[e.a]; ++edgeCount[e.b];
  }

  // The surrounding triangles at every boundary vertex, for the fairing's fixed ring.
  std::vector<bool> onBoundary(nv, false);
  for (const MeshHole& h : detection.holes)
    for (int v : h.loop) onBoundary[v] = true;
  std::vector<std::vector<int>> incident(nv);
  for (Eigen::Index t = 0; t < mesh.triangles.rows(); ++t)
    for (int k = 0; k < 3; ++k)
      if (onBoundary[mesh.triangles(t, k)]) incident[mesh.triangles(t, k)].push_back(static_cast<int>(t));

  std::vector<Eigen::Vector3d> newPoints;
  std::vector<Eigen::Vector3i> newTriangles;
  std::unordered_set<std::uint64_t> addedEdges;
  auto joined = [&](int u, int v) { return topo.hasEdge(u, v) || addedEdges.count(MeshTopology::key(u, v)) > 0; };

  // The pairs of triangles of a patch (its boundary on the loop's vertices, its new points after)
  // that cross each other, the surface around it, or an earlier hole's new triangles: those of
  // them whose boxes overlap the patch's, on their own indices (self_intersection.h).
  std::vector<Eigen::AlignedBox3d> boxes;
  if (options.checkCrossings) {
    boxes.reserve(mesh.triangles.rows());
    for (Eigen::Index t = 0; t < mesh.triangles.rows(); ++t) {
      Eigen::AlignedBox3d b;
      for (int k = 0; k < 3; ++k) b.extend(point(mesh.triangles(t, k)));
      boxes.push_back(b);
    }
  }
  auto patchCrossings = [&](const HolePatch& p, const std::vector<int>& loop) {
    const int n = p.boundaryCount;
    Eigen::AlignedBox3d box;
    for (const Eigen::Vector3d& x : p.points) box.extend(x);
    std::unordered_map<long long, int> localOf;  // ≥ 0: a mesh vertex (input or new); < 0: a patch point −1−i
    std::vector<Eigen::Vector3d> pts;
    std::vector<Eigen::Vector3i> tris;
    std::vector<bool> subject;
    const auto vertexOf = [&](long long key, const Eigen::Vector3d& x) {
      auto it = localOf.find(key);
      if (it != localOf.end()) return it->second;
      pts.push_back(x);
      return localOf.emplace(key, static_cast<int>(pts.size()) - 1).first->second;
    };
    const auto global = [&](int g) { return g < nv ? point(g) : newPoints[g - nv]; };
    for (const auto& t : p.triangles) {
      Eigen::Vector3i f;
      for (int k = 0; k < 3; ++k) f[k] = t[k] < n ? vertexOf(loop[t[k]], p.points[t[k]]) : vertexOf(-1 - t[k], p.points[t[k]]);
      tris.push_back(f);
      subject.push_back(true);
    }
    for (Eigen::Index t = 0; t < mesh.triangles.rows(); ++t)
      if (boxes[t].intersects(box)) {
        Eigen::Vector3i f;
        for (int k = 0; k < 3; ++k) f[k] = vertexOf(mesh.triangles(t, k), point(mesh.triangles(t, k)));
        tris.push_back(f);
        subject.push_back(false);
      }
    for (const Eigen::Vector3i& t : newTriangles) {
      Eigen::AlignedBox3d b;
      for (int k = 0; k < 3; ++k) b.extend(global(t[k]));
      if (!b.intersects(box)) continue;
      Eigen::Vector3i f;
      for (int k = 0; k < 3; ++k) f[k] = vertexOf(t[k], global(t[k]));
      tris.push_back(f);
      subject.push_back(false);
    }
    TriangleMesh local;
    local.vertices.resize(static_cast<Eigen::Index>(pts.size()), 3);
    for (size_t i = 0; i < pts.size(); ++i) local.vertices.row(static_cast<Eigen::Index>(i)) = pts[i].transpose();
    local.triangles.resize(static_cast<Eigen::Index>(tris.size()), 3);
    for (size_t i = 0; i < tris.size(); ++i) local.triangles.row(static_cast<Eigen::Index>(i)) = tris[i].transpose();
    const SelfIntersections si = selfIntersections(local, subject, 1000);
    if (std::getenv("HOLEFILL_DEBUG"))
      for (const auto& [a, b] : si.pairs)
        std::fprintf(stderr, "[mesh fill] crossing: %d (%s: %d %d %d) x %d (%s: %d %d %d) of %zu patch triangles\n", a,
                     subject[a] ? "patch" : "mesh", tris[a][0], tris[a][1], tris[a][2], b, subject[b] ? "patch" : "mesh", tris[b][0],
                     tris[b][1], tris[b][2], p.triangles.size());
    return static_cast<int>(si.pairs.size());
  };

  const int holeCount = static_cast<int>(detection.holes.size());
  for (int h = 0; h < holeCount; ++h) {
    const MeshHole& hole = detection.holes[h];
    MeshHoleFill fill;
    fill.hole = h;
    fill.boundaryVertices = static_cast<int>(hole.loop.size());
    fill.length = hole.length;
    fill.message = hole.message;
    const auto holeStart = std::chrono::steady_clock::now();
    auto skip = [&](const std::string& why) { fill.message = why + (hole.message.empty() ? "" : " (" + hole.message + ")"); };
    if (result.cancelled) {
      skip("not filled: cancelled");
    } else if (!hole.fillable) {
      fill.message = hole.message;
    } else if (!wanted[h]) {
      skip("not filled: not asked for");
    } else if (options.maxBoundary > 0 && fill.boundaryVertices > options.maxBoundary) {
      skip("not filled: " + std::to_string(fill.boundaryVertices) + " boundary vertices exceed the limit of " +
           std::to_string(options.maxBoundary) + " (maxBoundary, --max-boundary; 0 lifts it)");
    } else {
      try {
        const std::vector<int>& loop = hole.loop;
        const int n = static_cast<int>(loop.size());
        // One patch for the hole under options `o`, from the initial triangulation `start`: the
        // minimum-angle ear cutting, Liepa's minimum-dihedral program, or a fan from a new vertex at
        // the loop's centroid (the last resort where both would repeat an edge the mesh has: a loop
        // whose vertices the surrounding mesh already joins, across a singular vertex).
        enum class Start { Angle, Dihedral, Fan };
        auto makePatch = [&](const MeshFillOptions& o, Start start, MeshHoleFill& f) {
          HolePatch patch;
          patch.boundaryCount = n;
          std::vector<Eigen::Vector3d> sums(n), across(n);
          for (int i = 0; i < n; ++i) {
            patch.points.push_back(point(loop[i]));
            sums[i] = normalSum[loop[i]];
            patch.scale.push_back(edgeCount[loop[i]] ? edgeSum[loop[i]] / edgeCount[loop[i]] : 0.0);
            across[i] = orientedNormal(hole.edgeTriangles[i]).normalized();
          }
          patch.outsideEdge = [&](int i, int j) { return joined(loop[i], loop[j]); };
          f.splits = f.swaps = 0;
          f.sigma = 0;
          if (start == Start::Fan) {
            Eigen::Vector3d centre = Eigen::Vector3d::Zero();
            for (int i = 0; i < n; ++i) centre += patch.points[i] / n;
            double spacing = 0;
            for (int i = 0; i < n; ++i) spacing += patch.scale[i] / n;
            patch.points.push_back(centre);
            patch.scale.push_back(spacing);
            for (int i = 0; i < n; ++i) patch.triangles.push_back({(i + 1) % n, i, n});  // against the loop, as the others
            f.triangulation = "fan";
          } else if (start == Start::Dihedral && n <= o.maxDihedralLoop) {
            patch.triangles = triangulateMinDihedral(patch.points, across, patch.outsideEdge);
            f.triangulation = "dihedral";
          } else {
            f.triangulation = "angle";
            const MinAngleResult tri = triangulateMinAngle(patch.points, sums, across, patch.outsideEdge, o.triangulation);
            patch.triangles = tri.triangles;
            f.sigma = tri.sigma;
          }
          HolePatch bare;  // the relaxed initial triangulation, for the planar-hole fallback below
          if (o.keepBetterBare || !o.refine) {
            bare = patch;
            PatchEdges edges(bare);
            relaxAllEdges(bare, edges, o.refinement);
          }
          if (!o.refine) return bare;
          const RefinementResult ref = refinePatch(patch, o.refinement);
          f.splits = ref.splits;
          f.swaps = ref.swaps;
          if (ref.capped && f.message.find("safety cap") == std::string::npos)
            f.message += std::string(f.message.empty() ? "" : "; ") + "refinement stopped at a safety cap";
          const QualityResult improved = improvePatchQuality(patch, o.quality, o.refinement);
          f.swaps += improved.swaps;
          f.splits += improved.splits;
          SurroundingRing ring;
          {
            std::unordered_map<int, int> local;  // mesh vertex → patch/ring index
            for (int i = 0; i < n; ++i) local[loop[i]] = i;
            std::unordered_set<int> seen;
            for (int i = 0; i < n; ++i)
              for (int t : incident[loop[i]]) {
                if (!seen.insert(t).second) continue;
                std::array<int, 3> tri;
                int c = mesh.triangles(t, 0);
                for (int k = 0; k < 3; ++k, c = topo.nextVertex(t, c)) {
                  auto it = local.find(c);
                  if (it == local.end()) {
                    it = local.emplace(c, n + static_cast<int>(ring.points.size())).first;
                    ring.points.push_back(point(c));
                  }
                  tri[k] = it->second;
                }
                ring.triangles.push_back(tri);
              }
          }
          for (int pass = 0; pass < std::max(1, o.shape.passes); ++pass) {
            if (pass > 0) {
              PatchEdges edges(patch);
              f.swaps += relaxAllEdges(patch, edges, o.refinement);
            }
            fairLaplacian(patch, ring, o.shape);
          }
          bilateralFair(patch, o.fairing);  // fairing.iterations 0: off
          // Fairing moved vertices along normals: let smoothing and splits tidy up once more
          // (each step kept only if the worst triangle does not get worse).
          QualityOptions tidy = o.quality;
          tidy.rounds = std::min(tidy.rounds, 2);
          tidy.smoothing.iterations = std::min(tidy.smoothing.iterations, 3);
          const QualityResult tidied = improvePatchQuality(patch, tidy, o.refinement);
          f.swaps += tidied.swaps;
          f.splits += tidied.splits;

          // A planar hole whose bare triangulation already has the better worst triangle (a
          // removed sliver, a 3-vertex gap) is kept bare: new vertices cannot improve its shape,
          // which the bare triangles carry exactly, and here they only spoil its worst triangle.
          if (o.keepBetterBare && worstQuality(bare) > worstQuality(patch)) {
            Eigen::MatrixX3d P(n, 3);
            for (int i = 0; i < n; ++i) P.row(i) = bare.points[i].transpose();
            const Eigen::RowVector3d c = P.colwise().mean();
            const Eigen::MatrixX3d D = P.rowwise() - c;
            const double spread = std::sqrt(std::max(0.0, Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(D.transpose() * D / n).eigenvalues()[0]));
            if (spread <= 1e-3 * boundingDiagonal(P)) return bare;
          }
          return patch;
        };
        bool dihedral = options.initial == MeshFillOptions::Triangulation::MinDihedral;
        if (options.initial == MeshFillOptions::Triangulation::Auto) {
          // A crease reaching the loop: two surrounding triangles at a loop vertex, sharing an
          // edge, whose normals differ by more than the crease angle.
          bool crease = false;
          for (int i = 0; i < n && !crease; ++i)
            for (int t : incident[loop[i]])
              for (int u : incident[loop[i]]) {
                if (u <= t) continue;
                int shared = 0;
                for (int a = 0; a < 3; ++a)
                  for (int b = 0; b < 3; ++b) shared += mesh.triangles(t, a) == mesh.triangles(u, b) ? 1 : 0;
                const Eigen::Vector3d nt = orientedNormal(t), nu = orientedNormal(u);
                if (shared == 2 && nt.norm() > 0 && nu.norm() > 0 &&
                    angleBetween(nt, nu) > options.creaseAngle)
                  crease = true;
              }
          dihedral = !crease;
        }
        const Start first = dihedral ? Start::Dihedral : Start::Angle, other = dihedral ? Start::Angle : Start::Dihedral;
        HolePatch patch;
        try {
          patch = makePatch(options, first, fill);
        } catch (const Error& e) {
          // Neither triangulation may repeat an edge the mesh has: the other one, then the fan.
          const std::string why = e.what();
          try {
            patch = makePatch(options, other, fill);
          } catch (const Error&) {
            patch = makePatch(options, Start::Fan, fill);
          }
          fill.fallback = "the " + fill.triangulation + " initial triangulation (" + why + ")";
          fill.message += std::string(fill.message.empty() ? "" : "; ") + "filled from " + fill.fallback;
        }
        if (options.checkCrossings) {
          // A patch whose triangles cross each other or the surface around the hole is no valid
          // fill: fall back step by step to a plainer one until none crosses (the one crossing
          // least is kept, and said, when none is clean).
          int crossings = patchCrossings(patch, loop);
          bool refilled = false;
          struct Step {
            std::string name;
            MeshFillOptions o;
            Start start;
          };
          std::vector<Step> steps;
          MeshFillOptions o = options;
          o.fairing.iterations = 0;
          steps.push_back({"without the bilateral filter", o, first});
          o.shape.order = 0;
          steps.push_back({"flat placement (the paper's), no bilateral filter", o, first});
          // The ear cutting can overlap its own ears in a concave hole (it never tests them in a
          // plane); the other initial triangulation often does not.
          steps.push_back({std::string("the ") + (dihedral ? "minimum-angle" : "minimum-dihedral") +
                               " initial triangulation, flat, no bilateral filter", o, other});
          o.refine = false;
          steps.push_back({"the bare triangulation", o, first});
          steps.push_back({std::string("the bare ") + (dihedral ? "minimum-angle" : "minimum-dihedral") + " triangulation", o, other});
          for (size_t k = 0; k < steps.size() && crossings > 0; ++k) {
            MeshHoleFill f = fill;
            HolePatch p;
            try {
              p = makePatch(steps[k].o, steps[k].start, f);
            } catch (const Error&) {
              continue;  // this step's triangulation repeats an edge: the next
            }
            const int c = patchCrossings(p, loop);
            if (c < crossings) {
              crossings = c;
              patch = std::move(p);
              f.fallback = steps[k].name;
              fill = f;
              refilled = true;
            }
          }
          fill.crossings = crossings;
          if (refilled)
            fill.message += std::string(fill.message.empty() ? "" : "; ") + "its first patch crossed itself or the surface: " +
                            fill.fallback + (crossings > 0 ? ", still crossing (" + std::to_string(crossings) + " pairs)" : "");
          else if (crossings > 0)
            fill.message += std::string(fill.message.empty() ? "" : "; ") + "crosses itself or the surface (" + std::to_string(crossings) +
                            " pairs) whatever the fallback";
        }
        const int base = static_cast<int>(nv + newPoints.size());
        auto global = [&](int i) { return i < n ? loop[i] : base + (i - n); };
        for (size_t i = n; i < patch.points.size(); ++i) {
          HF_CHECK(patch.points[i].allFinite(), "a new vertex is not finite");
          newPoints.push_back(patch.points[i]);
        }
        double sum = 0;
        fill.minQuality = 1;
        for (const auto& t : patch.triangles) {
          const double q = triangleQuality(patch.points[t[0]], patch.points[t[1]], patch.points[t[2]]);
          fill.minQuality = std::min(fill.minQuality, q);
          fill.maxQuality = std::max(fill.maxQuality, q);
          fill.goodShare += q >= 0.7 ? 1 : 0;
          sum += q;
          newTriangles.emplace_back(global(t[0]), global(t[1]), global(t[2]));
          for (int k = 0; k < 3; ++k) addedEdges.insert(MeshTopology::key(global(t[k]), global(t[(k + 1) % 3])));
        }
        fill.newVertices = static_cast<int>(patch.points.size()) - n;
        fill.newTriangles = static_cast<int>(patch.triangles.size());
        fill.meanQuality = sum / fill.newTriangles;
        fill.goodShare /= fill.newTriangles;
        fill.filled = true;
      } catch (const Error& e) {
        fill.message = std::string("not filled: ") + e.what();
      }
    }
    fill.seconds = secondsSince(holeStart);
    (fill.filled ? result.filledHoles : result.openHoles)++;
    result.fills.push_back(std::move(fill));
    if (options.progress && !result.cancelled && !options.progress(double(h + 1) / holeCount)) result.cancelled = true;
  }

  result.mesh.vertices.resize(nv + static_cast<Eigen::Index>(newPoints.size()), 3);
  result.mesh.vertices.topRows(nv) = mesh.vertices;
  for (size_t i = 0; i < newPoints.size(); ++i) result.mesh.vertices.row(nv + i) = newPoints[i].transpose();
  const Eigen::Index nt = mesh.triangles.rows();
  result.mesh.triangles.resize(nt + static_cast<Eigen::Index>(newTriangles.size()), 3);
  result.mesh.triangles.topRows(nt) = mesh.triangles;
  for (size_t i = 0; i < newTriangles.size(); ++i) result.mesh.triangles.row(nt + i) = newTriangles[i].transpose();

  // Each filled loop closes exactly its own boundary edges, unless it was split at duplicated
  // vertices (its closing edge then ends at a copy): count only when that is not decisive.
  size_t closedEdges = 0;
  bool atCopies = false;
  for (const MeshHoleFill& f : result.fills) {
    if (!f.filled) continue;
    const MeshHole& h = detection.holes[f.hole];
    closedEdges += h.loop.size();
    for (size_t k = 0; k < h.loop.size(); ++k) atCopies = atCopies || h.edgeEnds[k] != h.loop[(k + 1) % h.loop.size()];
  }
  result.closed = atCopies ? countBoundaryEdges(result.mesh) == 0 : closedEdges == static_cast<size_t>(detection.boundaryEdges);
  if (!result.closed) {
    // Only vertices on the input's boundary can have been left with a coincident partner: the
    // holes' and the seams' (which are on no hole).
    std::vector<int> candidates;
    for (const MeshHole& h : detection.holes) candidates.insert(candidates.end(), h.loop.begin(), h.loop.end());
    if (detection.seamEdges > 0) candidates.clear();  // every vertex, then
    result.closedWhenWelded =
        countBoundaryEdges(result.mesh, weldMap(result.mesh.vertices, 1e-9 * boundingDiagonal(mesh.vertices), candidates)) == 0;
  } else {
    result.closedWhenWelded = true;
  }
  result.seconds = secondsSince(start);
  return result;
}

MeshFillOptions paperPipeline(MeshFillOptions o) {
  const MeshFillOptions d;
  o.initial = MeshFillOptions::Triangulation::MinAngle;
  o.refine = true;
  o.keepBetterBare = false;
  o.checkCrossings = false;
  o.triangulation = d.triangulation;
  o.refinement = d.refinement;
  o.quality.rounds = 0;
  o.quality.smoothing.iterations = 0;
  o.shape.order = 0;
  o.fairing.iterations = 3;
  o.fairing.closenessScale = 0.1;
  o.fairing.featureScale = 0.5;
  return o;
}

bool isPaperPipeline(const MeshFillOptions& o) {
  const MeshFillOptions p = paperPipeline(o);
  return o.initial == p.initial && o.refine == p.refine && o.keepBetterBare == p.keepBetterBare &&
         o.checkCrossings == p.checkCrossings && o.refinement.densityFactor == p.refinement.densityFactor &&
         o.quality.rounds == p.quality.rounds && o.quality.smoothing.iterations == p.quality.smoothing.iterations &&
         o.shape.order == p.shape.order && o.fairing.iterations == p.fairing.iterations &&
         o.fairing.closenessScale == p.fairing.closenessScale && o.fairing.featureScale == p.fairing.featureScale;
}

Outcome MeshFillResult::outcome() const {
  Outcome o;
  for (const MeshHoleFill& f : fills)
    if (!f.filled) o.faulting.push_back(f.hole);
  o.warnings = warnings;
  if (cancelled) {
    o.status = Status::Cancelled;
    o.stage = "fill";
    o.message = "cancelled";
  } else if (filledHoles == 0 && openHoles > 0) {
    o.status = Status::Failed;
    o.stage = "fill";
    std::set<std::string> reasons;
    for (const MeshHoleFill& f : fills)
      if (!f.message.empty()) reasons.insert(f.message);
    o.message = "no hole was filled";
    for (const auto& why : reasons) o.message += (why == *reasons.begin() ? ": " : "; ") + why;
  } else if (openHoles > 0) {
    o.status = Status::Warned;
    o.message = std::to_string(openHoles) + " of " + std::to_string(fills.size()) + " holes left open";
  } else {
    o.message = std::to_string(filledHoles) + " holes filled";
  }
  return o;
}

std::string MeshFillResult::toJson() const {
  JsonWriter w;
  w.beginObject();
  writeOutcomeFields(w, outcome());
  w.field("vertices", static_cast<int>(mesh.vertices.rows()));
  w.field("triangles", static_cast<int>(mesh.triangles.rows()));
  w.field("holes", static_cast<int>(fills.size()));
  w.field("filled", filledHoles);
  w.field("open", openHoles);
  w.field("closed", closed);
  w.field("closed_when_welded", closedWhenWelded);
  w.field("cancelled", cancelled);
  w.field("welded_vertices", weldedVertices);
  w.field("dropped_triangles", droppedTriangles);
  w.field("seconds", seconds);
  w.key("topology").beginObject();
  w.field("boundary_edges", detection.boundaryEdges);
  w.field("non_manifold_edges", detection.nonManifoldEdges);
  w.field("inconsistent_edges", detection.inconsistentEdges);
  w.field("singular_vertices", detection.singularVertices);
  w.field("components", detection.components);
  w.field("duplicate_vertex_splits", detection.duplicateSplits);
  w.endObject();
  w.field("warnings", warnings);
  w.key("hole_fills").beginArray();
  for (const MeshHoleFill& f : fills) {
    w.beginObject();
    w.field("hole", f.hole);
    w.field("boundary_vertices", f.boundaryVertices);
    w.field("length", f.length);
    w.field("filled", f.filled);
    w.field("message", f.message);
    w.field("new_vertices", f.newVertices);
    w.field("new_triangles", f.newTriangles);
    w.field("min_quality", f.minQuality);
    w.field("max_quality", f.maxQuality);
    w.field("mean_quality", f.meanQuality);
    w.field("share_quality_0_7", f.goodShare);
    w.field("sigma_deg", f.sigma * 180 / M_PI);
    w.field("triangulation", f.triangulation).field("fallback", f.fallback).field("crossings", f.crossings);
    w.field("splits", f.splits);
    w.field("swaps", f.swaps);
    w.field("seconds", f.seconds);
    w.endObject();
  }
  w.endArray();
  w.endObject();
  return w.str();
}

}  // namespace holefill

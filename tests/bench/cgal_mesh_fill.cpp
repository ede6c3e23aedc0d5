// The CGAL peer of the mesh-fill benchmark: Polygon Mesh Processing's
// triangulate_refine_and_fair_hole (Liepa 2003) with CGAL's defaults on every border cycle of
// at most MAX_BOUNDARY edges (0: all), as a CGAL user would run it. The mesh is read with
// CGAL's plain reader first and, when that refuses it (non-manifold vertices, duplicated
// corners), with the PMP reader that repairs and orients the polygon soup.
// Prints one JSON line {read, holes, filled, seconds (the fills), build_seconds (polygon soup
// to halfedge mesh, the step an arrays-in caller pays, as HoleFill does)}; writes the result as OFF.
// Usage: holefill_bench_cgal_fill IN OUT.off [MAX_BOUNDARY]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/Surface_mesh.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <set>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
namespace PMP = CGAL::Polygon_mesh_processing;

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s IN OUT.off [MAX_BOUNDARY]\n", argv[0]);
    return 1;
  }
  const int maxBoundary = argc > 3 ? std::atoi(argv[3]) : 0;
  Mesh mesh;
  std::string how = "plain";
  double buildSeconds = -1;
  {
    std::vector<Kernel::Point_3> points;
    std::vector<std::vector<std::size_t>> polygons;
    if (CGAL::IO::read_polygon_soup(argv[1], points, polygons) && PMP::is_polygon_soup_a_polygon_mesh(polygons)) {
      const auto t0 = std::chrono::steady_clock::now();
      PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
      buildSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    }
  }
  if (mesh.is_empty() && (!CGAL::IO::read_polygon_mesh(argv[1], mesh) || mesh.is_empty())) {
    mesh.clear();
    how = "repaired";
    if (!PMP::IO::read_polygon_mesh(argv[1], mesh) || mesh.is_empty()) {
      std::printf("{\"read\":\"failed\",\"holes\":0,\"filled\":0,\"seconds\":0}\n");
      return 2;
    }
  }
  std::vector<Mesh::Halfedge_index> borders;
  std::set<Mesh::Halfedge_index> seen;
  for (Mesh::Halfedge_index h : mesh.halfedges()) {
    if (!mesh.is_border(h) || seen.count(h)) continue;
    int n = 0;
    for (Mesh::Halfedge_index g : CGAL::halfedges_around_face(h, mesh)) {
      seen.insert(g);
      ++n;
    }
    if (maxBoundary <= 0 || n <= maxBoundary) borders.push_back(h);
  }
  int filled = 0;
  const auto start = std::chrono::steady_clock::now();
  for (Mesh::Halfedge_index h : borders) {
    std::vector<Mesh::Face_index> faces;
    std::vector<Mesh::Vertex_index> vertices;
    try {
      const auto r = PMP::triangulate_refine_and_fair_hole(mesh, h, std::back_inserter(faces), std::back_inserter(vertices));
      if (std::get<0>(r)) ++filled;
    } catch (const std::exception&) {
      // counted as not filled
    }
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::ofstream out(argv[2]);
  out.precision(17);
  const bool written = CGAL::IO::write_OFF(out, mesh);
  std::printf("{\"read\":\"%s\",\"holes\":%zu,\"filled\":%d,\"seconds\":%.6f,\"build_seconds\":%.6f,\"written\":%s}\n",
              how.c_str(), borders.size(), filled, seconds, buildSeconds, written ? "true" : "false");
  return 0;
}

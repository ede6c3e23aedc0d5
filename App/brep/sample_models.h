// Sample models with holes, built in code so tests need no files and the
// bundled samples in Resources/samples/ can be regenerated (`holefill samples DIR`):
// a Catmull-Clark extraordinary-point hole (the N quads around a valence-N vertex
// removed from a ring of bicubic limit patches), a filleted box with one corner
// vertex blend removed, a free-form B-spline panel with an irregular curved
// N-sided hole, and small models for detection tests (box minus a face, an open
// cylinder whose loop meets a seam, a sheet with two holes, a non-manifold fin).
#pragma once

#include <TopoDS_Edge.hxx>
#include <TopoDS_Shape.hxx>
#include <string>
#include <vector>

namespace holefill::samples {

// Valence-N vertex, R rings of quads per sector (R >= 3); `bend` scales the height field;
// `jitter` > 0 moves every control vertex by up to jitter*spacing (seeded) for irregular cages.
TopoDS_Shape ccExtraordinaryHole(int valence, int rings = 4, double bend = 1.0, double spacing = 10.0,
                                 double jitter = 0.0, unsigned seed = 0);
TopoDS_Shape filletedBoxCorner(double dx = 100, double dy = 80, double dz = 60, double radius = 12);
// The same box (100 x 80 x 60, radius 12) without its corner blend and the longest cylindrical fillet
// next to it: one loop around two adjacent holes; `divider` gets a copy of the edge the two faces
// shared (no face uses it, as a curve sketched across the hole), which splits the loop into them.
TopoDS_Shape filletedBoxAdjacentHoles(TopoDS_Edge* divider = nullptr);
// B-spline panel (100 x 100) with an irregular N-sided hole of curved sides; `seed` varies its shape.
TopoDS_Shape panelWithHole(int sides = 6, unsigned seed = 1);
// A single-span bicubic (Bezier) face with an irregular 5-sided hole: filling it on the exact pcurves reproduces it.
TopoDS_Shape bezierPatchWithHole();
TopoDS_Shape boxMinusFace();
TopoDS_Shape openCylinder();
TopoDS_Shape sheetWithTwoHoles();
TopoDS_Shape nonManifoldFin();

struct NamedSample {
  std::string name;
  TopoDS_Shape shape;
};
std::vector<NamedSample> demoSamples();  // the three samples the demo fills
// Any sample by name: the demo names, "cc_valence<N>", "box_minus_face", "bezier_patch_with_hole",
// "sheet_two_holes", "open_cylinder", "non_manifold_fin"; throws for unknown names.
TopoDS_Shape byName(const std::string& name);
std::vector<std::string> names();

}  // namespace holefill::samples

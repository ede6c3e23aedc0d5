// Quad cages of known topology, for tests, benchmarks, the demo and `holefill samples`: a
// polar cage around one EP, a disk around two adjacent EPs, and the cube (closed, with EPs
// that need a Catmull–Clark step). Vertices are lifted onto a smooth height field so the
// surfaces are curved.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "gnurbs/quad_cage.h"

namespace holefill::cages {

double height(double x, double y);

// A valence-n EP (vertex 0) with n sectors of k×k quads: sector i spans spokes i and i+1, its
// point (a, b) sits at a·e_i + b·e_{i+1} lifted onto height(), e_i at angle 2πi/n.
// interval(s, j): knot interval of the j-th edge out along spoke s and of every edge parallel to it.
QuadCage polarCage(int n, int k, const std::function<double(int, int)>& interval = [](int, int) { return 1.0; });

// Marks spoke line `spoke` of polarCage(n, k) sharp, from the EP (vertex 0) to the cage boundary.
void setSharpSpokeLine(QuadCage& polar, int k, int spoke);

// A disk of quads around edge 0-1 whose ends are EPs of valence nA (vertex 0) and nB (vertex 1),
// every other interior vertex regular: the star of the edge, then `rings` rings of quads (a
// polygon vertex inside one quad gets a corner quad, one inside two gets none, so every
// vertex a ring closes in has valence 4). Vertices are placed by Tutte's embedding (boundary on
// a circle of radius rings + 1.5) and lifted onto height().
QuadCage edgeStarCage(int nA, int nB, int rings);

// The cube [-1, 1]³, faces oriented outwards: a closed cage whose 8 corners are valence-3 EPs
// all sharing faces (it needs one Catmull–Clark step).
QuadCage cubeCage();

// The bundled sample cages by name (`holefill samples` writes them as OBJ).
std::vector<std::string> sampleCageNames();
QuadCage sampleCage(const std::string& name);

}  // namespace holefill::cages

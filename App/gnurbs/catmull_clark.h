// One Catmull–Clark refinement step of a quad cage (Catmull & Clark 1978; crease rules of
// DeRose et al. 1998), used to separate extraordinary points before the G² construction, as
// g2-gnurbs.md sec. 3 assumes: after one step every EP is an original vertex, no two EPs share
// a face or an edge, and EPs sit two edges apart at least. Sharp and boundary edges use the
// crease rules (edge point = midpoint; a vertex on two creases moves along them; on three or
// more it stays). Positions follow the uniform rules even on non-uniform cages; the children of
// an edge take half its knot interval and a new edge inside a face half the mean of the two face
// edges parallel to it, so the ratios the G² construction sees are kept. Children of sharp edges
// are sharp, and anchors stay on their vertex.
#pragma once

#include "gnurbs/quad_cage.h"

namespace holefill {

// Vertex order of the result: the original vertices' new positions (same indices, so sharp
// edges, anchors and EP numbers carry over), then one point per edge, then one per face. Face
// f's corner k becomes child face 4f + k, which has the original vertex as its corner 0.
QuadCage catmullClarkStep(const QuadCage& cage, const CageTopology& topo);

}  // namespace holefill

// Free loops that bound one opening together. A face whose boundary has an inner wire (an
// annulus: a washer's top, a flange between a bolt circle and its bore) leaves two free loops
// when it is missing, and hole detection finds each as a hole of its own; a face with one loop
// fills either of them as a cap over the other (the outer one capped with a dome over the bore,
// reported as G1 reached). Such an opening is recognized by its loops' nesting, as polygons with
// holes are: on the plane that fits a loop best, another loop whose points all lie strictly inside
// its projection and near that plane (within a tenth of its size) shares its opening. A loop
// inside the outer boundary of an open sheet does not: the sheet's material lies inside that
// boundary, and a hole in a sheet is one opening. A tube's two ends (the same circle seen along
// its axis, no point strictly inside) and a deep cup's rim over its own hole are not nested.
// Used by the fill (hole_fill.h) to refuse such an opening with a message naming both loops.
#pragma once

#include <vector>

#include "brep/hole_detection.h"

namespace holefill {

// The loops of `detection` (its holes and outer boundaries) other than `hole` that share its
// opening: those nested in it, and the holes it is nested in. Empty for an opening of one loop.
std::vector<const Hole*> loopsSharingOpening(const HoleDetectionResult& detection, const Hole& hole);

// The same for every loop of `detection` at once, each loop sampled and fitted by a plane once:
// [holes..., outer boundaries...] in that order, as a report of all holes needs them.
std::vector<std::vector<const Hole*>> loopsSharingOpenings(const HoleDetectionResult& detection);

}  // namespace holefill

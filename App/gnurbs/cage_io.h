// Quad cages in files. OBJ holds vertices (`v x y z`) and quads (`f a b c d`, 1-based, OBJ's
// `a/t/n` forms accepted); since OBJ has no standard for them, sharp edges and knot intervals
// sit in comment lines `# sharp i j` and `# knot i j d`, and anchors in `# anchor i x y z`
// (1-based vertex indices; other comments are ignored). Sharp edges and anchors may also come
// as JSON lists, `[[i, j], …]` and `[[i, x, y, z], …]`, 1-based likewise. Files are untrusted:
// every malformed line is an Error naming the file and line; a face that is not a quad is refused
// (the G-NURBS construction is for quad cages), and the cage is validated (CageTopology) after.
#pragma once

#include <string>

#include "gnurbs/quad_cage.h"

namespace holefill {

QuadCage parseCageObj(const std::string& bytes, const std::string& name = "cage");
QuadCage readCage(const std::string& path);  // .obj
std::string formatCageObj(const QuadCage& cage);

// Add the sharp edges / anchors of a JSON list (text) to the cage; `name` labels errors.
void addSharpEdgesFromJson(QuadCage& cage, const std::string& text, const std::string& name = "sharp edges");
void addAnchorsFromJson(QuadCage& cage, const std::string& text, const std::string& name = "anchors");

}  // namespace holefill

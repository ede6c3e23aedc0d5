// Reading and writing triangle meshes in the formats scanners and FreeCAD exchange: OBJ,
// OFF, PLY (ASCII and binary) and STL (ASCII and binary). Files are untrusted: counts are
// checked against the file size before anything is allocated, coordinates must be finite,
// indices in range; polygons are split into triangle fans; STL's unshared corners are welded
// where their coordinates are bit-identical (the only sharing STL can express). Writes are
// atomic. Every failure is a holefill::Error naming the file and the line or element.
#pragma once

#include <string>

#include "mesh/triangle_mesh.h"

namespace holefill {

// By extension (.obj, .off, .ply, .stl, case-insensitive).
TriangleMesh readMesh(const std::string& path);
// By extension: OBJ, OFF and PLY in ASCII, STL binary.
void writeMesh(const TriangleMesh& mesh, const std::string& path);

// Parsing from memory (tests, the Python door); `name` only labels error messages.
TriangleMesh parseMesh(const std::string& bytes, const std::string& extension, const std::string& name = "mesh");
std::string formatMesh(const TriangleMesh& mesh, const std::string& extension);

}  // namespace holefill

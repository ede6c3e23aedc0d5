// Reading and writing B-rep files as untrusted data (DESIGN.md "Files are
// untrusted"). OCCT's readers can hang on truncated BREP text and crash on
// malformed STEP, so a file is read under a time limit in a process that may die:
// inside a supervised child (geometry/supervised_child.h, the CLI) it is read once,
// as a step the parent watches; elsewhere it is first read in a throwaway child and,
// only when that succeeds, read in-process. Every shape entering the
// core is checked for finite, bounded coordinates. Writes go to a temporary file
// that is renamed into place, so a failure never leaves a half-written output.
#pragma once

#include <TopoDS_Shape.hxx>
#include <string>

namespace holefill {

// .brep / .brp (OCCT native) or .step / .stp; throws holefill::Error with a clear message.
TopoDS_Shape readShape(const std::string& path, double timeLimitSeconds = 60.0);
void writeShape(const TopoDS_Shape& shape, const std::string& path);  // by extension, atomically

// BREP text (the Python door's form of a shape): read like a file, under a time limit; 0: 5 s and
// 1 s per MB of text (OCCT reads about 75 MB/s), so a bad text holds FreeCAD seconds, not a minute.
TopoDS_Shape shapeFromBrepString(const std::string& brep, double timeLimitSeconds = 0);
std::string shapeToBrepString(const TopoDS_Shape& shape);

// Throws when a vertex, pole or curve/surface sample is NaN, infinite or beyond tol::kMaxCoordinate.
void validateShape(const TopoDS_Shape& shape);

}  // namespace holefill

// STEP files through OCCT's STEP translator, which lives in its own library (libholefill_step.so,
// geometry/plugin_library.h) loaded on first use: its OCCT libraries take 18 ms to load, a fifth
// of a whole `holefill fill` on a small model, and most calls never read or write STEP.
#pragma once

#include <TopoDS_Shape.hxx>
#include <string>

namespace holefill {

// Throw holefill::Error with the translator's message (or where the library was looked for);
// readStep's names the file, writeStep's does not (its caller writes to a temporary name).
TopoDS_Shape readStep(const std::string& path);
void writeStep(const TopoDS_Shape& shape, const std::string& path);

}  // namespace holefill

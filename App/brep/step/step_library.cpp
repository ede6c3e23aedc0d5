// libholefill_step.so: OCCT's STEP translator behind two plain entry points (brep/step_io.h loads
// this library on first use). Linked to OCCT's STEP libraries, and nothing else is; of the core it
// holds only geometry/error (one line for an OCCT exception, as everywhere else).
#include <IFSelect_ReturnStatus.hxx>
#include <Interface_Static.hxx>
#include <STEPControl_Reader.hxx>
#include <STEPControl_Writer.hxx>
#include <Standard_Failure.hxx>
#include <TopoDS_Shape.hxx>

#include <cstdio>
#include <string>

#include "geometry/error.h"

namespace {

int fail(char* err, int errLen, const std::string& message) {
  std::snprintf(err, static_cast<size_t>(errLen), "%s", message.c_str());
  return 1;
}

}  // namespace

extern "C" {

// Reads the STEP file at `path` into *out. Returns 0, or non-zero with a message in err.
int holefill_step_read(const char* path, TopoDS_Shape* out, char* err, int errLen) {
  try {
    STEPControl_Reader reader;
    if (reader.ReadFile(path) != IFSelect_RetDone) return fail(err, errLen, "not a valid STEP file");
    reader.TransferRoots();
    *out = reader.OneShape();
    return out->IsNull() ? fail(err, errLen, "it holds no shape") : 0;
  } catch (const Standard_Failure& e) {
    return fail(err, errLen, holefill::occtFailure(e));
  }
}

// Writes *shape to `path` as STEP AP214. Returns 0, or non-zero with a message in err.
int holefill_step_write(const TopoDS_Shape* shape, const char* path, char* err, int errLen) {
  try {
    STEPControl_Writer w;
    Interface_Static::SetCVal("write.step.schema", "AP214IS");
    if (w.Transfer(*shape, STEPControl_AsIs) != IFSelect_RetDone) return fail(err, errLen, "the STEP translator refused the shape");
    if (w.Write(path) != IFSelect_RetDone) return fail(err, errLen, "the STEP file could not be written");
    return 0;
  } catch (const Standard_Failure& e) {
    return fail(err, errLen, holefill::occtFailure(e));
  }
}

}  // extern "C"

#include "brep/step_io.h"

#include <dlfcn.h>

#include <mutex>

#include "geometry/error.h"
#include "geometry/plugin_library.h"

namespace holefill {

namespace {

using ReadFn = int (*)(const char*, TopoDS_Shape*, char*, int);
using WriteFn = int (*)(const TopoDS_Shape*, const char*, char*, int);

struct StepLibrary {
  ReadFn read = nullptr;
  WriteFn write = nullptr;
};

#ifdef HOLEFILL_BUILD_STEP_LIBRARY
constexpr const char* kBuildLibrary = HOLEFILL_BUILD_STEP_LIBRARY;
#else
constexpr const char* kBuildLibrary = nullptr;
#endif

const StepLibrary& stepLibrary() {
  static std::mutex m;
  static StepLibrary lib;
  std::lock_guard<std::mutex> lock(m);
  if (lib.read) return lib;
  std::string path, tried;
  void* h = openPluginLibrary("libholefill_step.so", "HOLEFILL_STEP_LIBRARY", kBuildLibrary, path, tried);
  if (!h) throw Error("STEP files need libholefill_step.so, which could not be loaded:" + tried);
  StepLibrary l;
  l.read = reinterpret_cast<ReadFn>(dlsym(h, "holefill_step_read"));
  l.write = reinterpret_cast<WriteFn>(dlsym(h, "holefill_step_write"));
  if (!l.read || !l.write) throw Error(path + " lacks the STEP entry points");
  lib = l;
  return lib;
}

}  // namespace

TopoDS_Shape readStep(const std::string& path) {
  TopoDS_Shape shape;
  char err[512] = "";
  if (stepLibrary().read(path.c_str(), &shape, err, sizeof err) != 0)
    throw Error("cannot read '" + path + "': " + err);
  return shape;
}

void writeStep(const TopoDS_Shape& shape, const std::string& path) {
  char err[512] = "";
  if (stepLibrary().write(&shape, path.c_str(), err, sizeof err) != 0)
    throw Error(err);
}

}  // namespace holefill

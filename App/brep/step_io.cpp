#include "brep/step_io.h"

#include <dlfcn.h>

#include <algorithm>
#include <cctype>
#include <mutex>
#include <unordered_set>
#include <utility>
#include <vector>

#include "geometry/error.h"
#include "geometry/plugin_library.h"
#include "geometry/text_file.h"

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

// OCCT's STEP reader takes a reference to an entity the file does not define as an empty
// slot: the shape comes back with a face, loop or point missing and nothing said (or it crashes,
// which the supervised read turns into an error). So the DATA section is checked first: every
// "#N" an entity refers to must be an entity the file defines. Quoted strings are skipped ('' is
// a quote inside one); comments (/* */) too.
void checkStepReferences(const std::string& text, const std::string& name) {
  const size_t data = text.find("DATA;");
  if (data == std::string::npos) throw Error("cannot read '" + name + "': no DATA section (not a STEP file, or cut off)");
  std::unordered_set<unsigned long long> defined;
  std::vector<std::pair<unsigned long long, size_t>> used;  // reference, its statement's start
  size_t statement = data + 5;
  bool atStart = true;  // before the statement's own "#N ="
  for (size_t i = data + 5; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '\'') {
      for (++i; i < text.size(); ++i)
        if (text[i] == '\'') {
          if (i + 1 < text.size() && text[i + 1] == '\'') ++i;
          else break;
        }
    } else if (c == '/' && i + 1 < text.size() && text[i + 1] == '*') {
      const size_t end = text.find("*/", i + 2);
      i = end == std::string::npos ? text.size() : end + 1;
    } else if (c == ';') {
      statement = i + 1;
      atStart = true;
    } else if (c == '#') {
      size_t j = i + 1;
      unsigned long long id = 0;
      while (j < text.size() && text[j] >= '0' && text[j] <= '9' && id < (1ULL << 60)) id = id * 10 + static_cast<unsigned long long>(text[j++] - '0');
      if (j == i + 1) continue;
      if (atStart) defined.insert(id);
      else used.emplace_back(id, statement);
      atStart = false;
      i = j - 1;
    } else if (!std::isspace(static_cast<unsigned char>(c))) {
      if (atStart && text.compare(i, 7, "ENDSEC;") == 0) break;
      atStart = false;
    }
  }
  for (const auto& [id, at] : used)
    if (!defined.count(id)) {
      const size_t from = std::min(text.size(), text.find_first_not_of(" \t\r\n", at));
      const size_t line = static_cast<size_t>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(from), '\n')) + 1;
      throw Error("cannot read '" + name + "': the entity on line " + std::to_string(line) + " refers to #" + std::to_string(id) +
                  ", which the file does not define (a damaged or cut STEP file)");
    }
}

}  // namespace

TopoDS_Shape readStep(const std::string& path) {
  checkStepReferences(readFileBytes(path), path);
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

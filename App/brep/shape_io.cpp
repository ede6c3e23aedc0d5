#include "brep/shape_io.h"

#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iostream>
#include <signal.h>
#include <sstream>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "brep/step_io.h"
#include "geometry/atomic_file.h"
#include "geometry/error.h"
#include "geometry/supervised_child.h"
#include "geometry/text_file.h"
#include "geometry/tolerances.h"

namespace holefill {

namespace {

bool finitePoint(const gp_Pnt& p) {
  return std::isfinite(p.X()) && std::isfinite(p.Y()) && std::isfinite(p.Z()) &&
         std::abs(p.X()) < tol::kMaxCoordinate && std::abs(p.Y()) < tol::kMaxCoordinate &&
         std::abs(p.Z()) < tol::kMaxCoordinate;
}

// OCCT's BREP reader loops for ever on a file cut off inside its TShapes section (it waits for
// each shape's "*"-terminated list of sub-shapes, and at the end of the stream it reads nothing,
// again and again), and it reads text with NUL bytes in it as if they ended a token. So the text
// is checked first: no NUL byte, a "TShapes N" section with N sub-shape lists ("*" ends each)
// and, after the last, the reference of the shape itself (an oriented index and a location).
void checkBrepText(const std::string& text, const std::string& name) {
  if (text.find('\0') != std::string::npos) throw Error(name + " is not a valid BREP file: it has NUL bytes in it (a binary or damaged file)");
  const size_t at = text.find("\nTShapes ");
  if (at == std::string::npos) throw Error(name + " is not a valid BREP file: it has no TShapes section (cut off, or not BREP)");
  std::istringstream in(text.substr(at + 9));
  long long count = -1;
  if (!(in >> count) || count < 0) throw Error(name + " is not a valid BREP file: its TShapes count is not a number");
  long long lists = 0;
  std::string token;
  std::vector<std::string> after;  // the tokens after the last "*"
  while (in >> token) {
    if (token == "*") ++lists, after.clear();
    else after.push_back(token);
  }
  const auto isIndex = [](const std::string& t, bool signedRef) {
    size_t k = 0;
    if (signedRef) {
      if (t.empty() || (t[0] != '+' && t[0] != '-')) return false;
      k = 1;
    }
    return t.size() > k && t.find_first_not_of("0123456789", k) == std::string::npos;
  };
  // The shape itself: an oriented index and its location (OCCT 7.6 writes a further flag line).
  const bool shape = after.size() >= 2 && isIndex(after[0], true) && isIndex(after[1], false);
  if (lists < count || !shape)
    throw Error(name + " is not a valid BREP file: it ends inside its TShapes section (" + std::to_string(lists) + " of " + std::to_string(count) +
                " shapes, then " + (shape ? "the shape" : "no shape") + "): the file was cut off");
}

TopoDS_Shape readInProcess(const std::string& path, const std::string& ext) {
  TopoDS_Shape shape;
  if (ext == "brep" || ext == "brp") {
    checkBrepText(readFileBytes(path), "'" + path + "'");
    BRep_Builder b;
    // OCCT's BREP reader says what it could not parse on std::cout, which would corrupt the
    // CLI's --json output: it is caught here and becomes part of the error instead.
    std::ostringstream said;
    std::streambuf* const out = std::cout.rdbuf(said.rdbuf());
    bool ok = false;
    try {
      ok = BRepTools::Read(shape, path.c_str(), b);
    } catch (...) {
      std::cout.rdbuf(out);
      throw;
    }
    std::cout.rdbuf(out);
    if (!ok || shape.IsNull()) {
      std::istringstream lines(said.str());
      std::string why, line;
      while (std::getline(lines, line))
        if (line.find_first_not_of(" \t\r") != std::string::npos) why += (why.empty() ? "" : "; ") + line;
      throw Error("cannot read '" + path + "': not a valid BREP file" + (why.empty() ? "" : " (" + why + ")"));
    }
  } else if (ext == "step" || ext == "stp") {
    shape = readStep(path);
  } else {
    throw Error("unsupported file type '" + ext + "' of '" + path + "': use .brep or .step");
  }
  return shape;
}

TopoDS_Shape readCheckedInProcess(const std::string& path, const std::string& ext) {
  TopoDS_Shape shape;
  try {
    shape = readInProcess(path, ext);
  } catch (const Standard_Failure& e) {
    throw Error("cannot read '" + path + "': " + e.GetMessageString());
  }
  validateShape(shape);
  return shape;
}

// Runs read in a throwaway child first (outside a supervised child): a hang or crash there costs
// only the child, and the caller then reads in its own process knowing the reader returns. A read
// that failed with an error in the child is left to the caller's read, which says why.
void trialReadInChild(const std::function<void()>& read, double timeLimit, const std::string& what, const std::string& name) {
  fflush(nullptr);
  const pid_t pid = fork();
  if (pid == 0) {
    // A crash here is the answer, not something to handle: the child dies of its signal and the
    // parent says so. FreeCAD's handlers (and OCCT's, which turn signals into exceptions) would
    // make a crash look like a clean read error, after which the caller reads the same bytes in
    // its own process (fuzzing found three such OCCT crashes: docs/fuzzing.md).
    for (int sig : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) signal(sig, SIG_DFL);
    int code = 1;
    try {
      read();
      code = 0;
    } catch (...) {
    }
    _exit(code);
  }
  if (pid < 0) return;  // no child to spare: read as before
  int status = 0;
  const int steps = static_cast<int>(timeLimit * 100);
  bool done = false;
  for (int i = 0; i < steps && !done; ++i) {
    if (waitpid(pid, &status, WNOHANG) == pid) done = true;
    else usleep(10000);
  }
  if (!done) {
    kill(pid, SIGKILL);
    waitpid(pid, &status, 0);
    throw Error(what + " took longer than " + std::to_string(int(timeLimit)) + " s: the data is corrupt or truncated");
  }
  if (WIFSIGNALED(status)) throw Error(name + " is corrupt: the reader crashed on it");
}

}  // namespace

void validateShape(const TopoDS_Shape& shape) {
  if (shape.IsNull()) throw Error("the shape is empty");
  TopTools_IndexedMapOfShape vs, es, fs;
  TopExp::MapShapes(shape, TopAbs_VERTEX, vs);
  TopExp::MapShapes(shape, TopAbs_EDGE, es);
  TopExp::MapShapes(shape, TopAbs_FACE, fs);
  for (int i = 1; i <= vs.Extent(); ++i)
    if (!finitePoint(BRep_Tool::Pnt(TopoDS::Vertex(vs(i)))))
      throw Error("the shape has a vertex with NaN, infinite or absurd coordinates (Vertex" + std::to_string(i) + ")");
  for (int i = 1; i <= es.Extent(); ++i) {
    Standard_Real a, b;
    Handle(Geom_Curve) c = BRep_Tool::Curve(TopoDS::Edge(es(i)), a, b);
    if (c.IsNull()) continue;
    if (!std::isfinite(a) || !std::isfinite(b)) throw Error("Edge" + std::to_string(i) + " has a non-finite range");
    Handle(Geom_BSplineCurve) bc = Handle(Geom_BSplineCurve)::DownCast(c);
    if (!bc.IsNull())
      for (int k = 1; k <= bc->NbPoles(); ++k)
        if (!finitePoint(bc->Pole(k))) throw Error("Edge" + std::to_string(i) + " has NaN or infinite poles");
  }
  for (int i = 1; i <= fs.Extent(); ++i) {
    Handle(Geom_Surface) s = BRep_Tool::Surface(TopoDS::Face(fs(i)));
    Handle(Geom_BSplineSurface) bs = Handle(Geom_BSplineSurface)::DownCast(s);
    if (bs.IsNull()) continue;
    for (int u = 1; u <= bs->NbUPoles(); ++u)
      for (int v = 1; v <= bs->NbVPoles(); ++v)
        if (!finitePoint(bs->Pole(u, v))) throw Error("Face" + std::to_string(i) + " has NaN or infinite poles");
  }
}

TopoDS_Shape readShape(const std::string& path, double timeLimit) {
  struct stat st;
  if (stat(path.c_str(), &st) != 0) throw Error("cannot open '" + path + "': no such file");
  if (!S_ISREG(st.st_mode)) throw Error("'" + path + "' is not a regular file");
  if (st.st_size == 0) throw Error("'" + path + "' is empty");
  const std::string ext = fileExtension(path);
  if (ext != "brep" && ext != "brp" && ext != "step" && ext != "stp")
    throw Error("unsupported file type '." + ext + "' of '" + path + "': use .brep or .step");
  if (supervised()) {
    // The whole command runs in a watched child already: one read, stopped by its time limit.
    SupervisedStep step("reading '" + path + "'", timeLimit, true);
    return readCheckedInProcess(path, ext);
  }
  trialReadInChild([&] { readCheckedInProcess(path, ext); }, timeLimit, "reading '" + path + "'", "'" + path + "'");
  return readCheckedInProcess(path, ext);
}

void writeShape(const TopoDS_Shape& shape, const std::string& path) {
  if (shape.IsNull()) throw Error("nothing to write to '" + path + "': the shape is empty");
  const std::string ext = fileExtension(path);
  if (ext != "brep" && ext != "brp" && ext != "step" && ext != "stp")
    throw Error("unsupported output type '." + ext + "' of '" + path + "': use .brep or .step");
  const std::string tmp = temporaryFileFor(path);
  bool ok = false;
  try {
    if (ext == "brep" || ext == "brp") {
      ok = BRepTools::Write(shape, tmp.c_str());
    } else {
      writeStep(shape, tmp);
      ok = true;
    }
  } catch (const Error& e) {
    std::remove(tmp.c_str());
    throw Error("cannot write '" + path + "': " + e.what());
  } catch (const Standard_Failure& e) {
    std::remove(tmp.c_str());
    throw Error("cannot write '" + path + "': " + e.GetMessageString());
  }
  if (!ok) std::remove(tmp.c_str());
  if (!ok || !commitTemporaryFile(tmp, path))
    throw Error("cannot write '" + path + "': check the folder exists and is writable");
}

TopoDS_Shape shapeFromBrepString(const std::string& brep, double timeLimit) {
  if (brep.empty()) throw Error("empty BREP text: the shape is empty");
  if (!(timeLimit > 0)) timeLimit = 5.0 + static_cast<double>(brep.size()) / 1e6;
  checkBrepText(brep, "the BREP text");
  const auto read = [&] {
    std::istringstream in(brep);
    TopoDS_Shape s;
    BRep_Builder b;
    try {
      BRepTools::Read(s, in, b);
    } catch (const Standard_Failure& e) {
      throw Error(std::string("invalid BREP text: ") + e.GetMessageString());
    }
    if (s.IsNull()) throw Error("invalid BREP text: no shape in it");
    validateShape(s);
    return s;
  };
  // OCCT's reader loops for ever on grammar errors checkBrepText cannot see (a token it fails to
  // read inside an edge's list of representations, found by fuzzing): the Python door must not
  // hang FreeCAD, so the text is read in a throwaway child first, as files are.
  if (supervised()) {
    SupervisedStep step("reading the BREP text", timeLimit, true);
    return read();
  }
  trialReadInChild([&] { read(); }, timeLimit, "reading the BREP text", "the BREP text");
  return read();
}

std::string shapeToBrepString(const TopoDS_Shape& shape) {
  std::ostringstream out;
  BRepTools::Write(shape, out);
  return out.str();
}

}  // namespace holefill

// holefill::Error is the one exception type the core throws. Its message says
// what was wrong and what to do about it; python/ maps it to a Python
// exception, cli/ to a non-zero exit with one line. HF_CHECK is the checked
// assertion of the core (geometry-central's GC_SAFETY_ASSERT): it throws with
// file:line so a violated invariant never turns into a crash inside FreeCAD.
#pragma once

#include <stdexcept>
#include <string>

class Standard_Failure;

namespace holefill {

class Error : public std::runtime_error {
public:
  explicit Error(const std::string& what) : std::runtime_error(what) {}
};

// One line for an OCCT exception caught at a door or a stage boundary: "OpenCASCADE failed: "
// and its message, or its exception type where OCCT gave none (many raise with an empty one,
// which left "OpenCASCADE failed:" and nothing to act on).
std::string occtFailure(const Standard_Failure& e);

[[noreturn]] void throwCheckFailed(const char* cond, const std::string& msg, const char* file, int line);

}  // namespace holefill

#define HF_CHECK(cond, msg)                                                  \
  do {                                                                       \
    if (!(cond)) ::holefill::throwCheckFailed(#cond, (msg), __FILE__, __LINE__); \
  } while (0)

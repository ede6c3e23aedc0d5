#include "geometry/error.h"

#include <Standard_Failure.hxx>
#include <Standard_Type.hxx>
#include <sstream>

namespace holefill {

std::string occtFailure(const Standard_Failure& e) {
  const char* msg = e.GetMessageString();
  std::string what = msg ? msg : "";
  while (!what.empty() && (what.back() == ' ' || what.back() == '\n')) what.pop_back();
  if (what.empty()) what = std::string(e.DynamicType()->Name()) + " (no message)";
  return "OpenCASCADE failed: " + what;
}

void throwCheckFailed(const char* cond, const std::string& msg, const char* file, int line) {
  std::ostringstream s;
  const char* base = file;
  for (const char* p = file; *p; ++p)
    if (*p == '/') base = p + 1;
  s << msg << " [" << base << ":" << line << ": " << cond << "]";
  throw Error(s.str());
}

}  // namespace holefill

#include "geometry/error.h"

#include <sstream>

namespace holefill {

void throwCheckFailed(const char* cond, const std::string& msg, const char* file, int line) {
  std::ostringstream s;
  const char* base = file;
  for (const char* p = file; *p; ++p)
    if (*p == '/') base = p + 1;
  s << msg << " [" << base << ":" << line << ": " << cond << "]";
  throw Error(s.str());
}

}  // namespace holefill

#include "geometry/atomic_file.h"

#include <cstdio>
#include <unistd.h>

#include "geometry/error.h"
#include "geometry/supervised_child.h"
#include "geometry/text_file.h"

namespace holefill {

std::string temporaryFileFor(const std::string& path) {
  const std::string ext = fileExtension(path);
  const std::string tmp = path + ".tmp" + std::to_string(getpid()) + (ext.empty() ? "" : "." + ext);
  noteTemporaryFile(tmp);
  return tmp;
}

bool commitTemporaryFile(const std::string& tmp, const std::string& path) {
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    return false;
  }
  noteOutputWritten(path);
  return true;
}

void writeFileAtomically(const std::string& path, const std::string& bytes) {
  const std::string tmp = temporaryFileFor(path);
  FILE* f = std::fopen(tmp.c_str(), "wb");
  bool ok = f != nullptr;
  if (f) {
    ok = std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size();
    ok = (std::fclose(f) == 0) && ok;
  }
  if (!ok) std::remove(tmp.c_str());
  if (!ok || !commitTemporaryFile(tmp, path))
    throw Error("cannot write '" + path + "': check that the folder exists and is writable");
}

}  // namespace holefill

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

OutputSet::~OutputSet() {
  for (const auto& [tmp, target] : staged_) std::remove(tmp.c_str());
}

std::string OutputSet::stage(const std::string& path) {
  const std::string ext = fileExtension(path);
  const std::string tmp = path + ".part" + std::to_string(getpid()) + (ext.empty() ? "" : "." + ext);
  noteTemporaryFile(tmp);
  staged_.emplace_back(tmp, path);
  return tmp;
}

void OutputSet::write(const std::string& path, const std::function<void(const std::string&)>& writer) {
  const std::string tmp = stage(path);
  try {
    writer(tmp);
  } catch (const Error& e) {
    std::string what = e.what();
    for (size_t at = what.find(tmp); at != std::string::npos; at = what.find(tmp, at + path.size())) what.replace(at, tmp.size(), path);
    throw Error(what);
  }
}

void OutputSet::commit() {
  std::vector<std::pair<std::string, std::string>> left = std::move(staged_);
  staged_.clear();
  for (size_t k = 0; k < left.size(); ++k)
    if (!commitTemporaryFile(left[k].first, left[k].second)) {
      for (size_t j = k + 1; j < left.size(); ++j) std::remove(left[j].first.c_str());
      throw Error("cannot write '" + left[k].second + "': check that the folder exists and is writable");
    }
}

}  // namespace holefill

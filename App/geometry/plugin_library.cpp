#include "geometry/plugin_library.h"

#include <dlfcn.h>
#include <sys/stat.h>

#include <cstdlib>
#include <vector>

namespace holefill {

bool fileExists(const std::string& path) {
  struct stat st;
  return !path.empty() && ::stat(path.c_str(), &st) == 0;
}

std::string directoryOf(const std::string& path) {
  const auto k = path.find_last_of('/');
  return k == std::string::npos ? "." : path.substr(0, k);
}

std::string thisModuleDirectory() {
  Dl_info info;
  if (dladdr(reinterpret_cast<void*>(&thisModuleDirectory), &info) && info.dli_fname) return directoryOf(info.dli_fname);
  return ".";
}

void* openPluginLibrary(const std::string& fileName, const char* envVariable, const char* buildPath, std::string& path,
                        std::string& tried) {
  std::vector<std::string> candidates;
  if (const char* e = envVariable ? std::getenv(envVariable) : nullptr) candidates.push_back(e);
  candidates.push_back(thisModuleDirectory() + "/" + fileName);
  if (buildPath) candidates.push_back(buildPath);
  tried.clear();
  for (const auto& c : candidates) {
    if (!fileExists(c)) { tried += " " + c + " (missing);"; continue; }
    void* h = dlopen(c.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!h) { tried += " " + c + " (" + dlerror() + ");"; continue; }
    path = c;
    return h;
  }
  return nullptr;
}

}  // namespace holefill

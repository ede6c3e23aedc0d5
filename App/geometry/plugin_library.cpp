#include "geometry/plugin_library.h"

#include <dlfcn.h>
#include <sys/stat.h>

#include <cstdlib>
#include <vector>

namespace holefill {

namespace {

bool exists(const std::string& p) {
  struct stat st;
  return !p.empty() && ::stat(p.c_str(), &st) == 0;
}

}  // namespace

std::string thisModuleDirectory() {
  Dl_info info;
  if (dladdr(reinterpret_cast<void*>(&thisModuleDirectory), &info) && info.dli_fname) {
    const std::string p = info.dli_fname;
    const auto k = p.find_last_of('/');
    return k == std::string::npos ? "." : p.substr(0, k);
  }
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
    if (!exists(c)) { tried += " " + c + " (missing);"; continue; }
    void* h = dlopen(c.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!h) { tried += " " + c + " (" + dlerror() + ");"; continue; }
    path = c;
    return h;
  }
  return nullptr;
}

}  // namespace holefill

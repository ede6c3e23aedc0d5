#include "learn/learn_library.h"

#include <dlfcn.h>

#include <mutex>
#include <vector>

#include "geometry/error.h"
#include "geometry/plugin_library.h"

namespace holefill::learn {

namespace {

#ifdef HOLEFILL_BUILD_LEARN_LIBRARY
constexpr const char* kBuildLibrary = HOLEFILL_BUILD_LEARN_LIBRARY;
#else
constexpr const char* kBuildLibrary = nullptr;
#endif

}  // namespace

const LearnLibrary& learnLibrary() {
  static std::mutex m;
  static LearnLibrary lib;
  static std::string failure;
  std::lock_guard<std::mutex> lock(m);
  if (lib.predict) return lib;
  if (!failure.empty()) throw Error(failure);
  std::string path, tried;
  void* h = openPluginLibrary("libholefill_learn.so", "HOLEFILL_LEARN_LIBRARY", kBuildLibrary, path, tried);
  if (h) {
    LearnLibrary l;
    l.path = path;
    l.predict = reinterpret_cast<HoleFillUvtranPredictFn>(dlsym(h, "holefill_uvtran_predict"));
    l.bidgcnPredict = reinterpret_cast<HoleFillBidgcnPredictFn>(dlsym(h, "holefill_bidgcn_predict"));
    l.main = reinterpret_cast<HoleFillLearnMainFn>(dlsym(h, "holefill_learn_main"));
    l.info = reinterpret_cast<HoleFillLearnInfoFn>(dlsym(h, "holefill_learn_info"));
    if (l.predict && l.bidgcnPredict && l.main && l.info) {
      lib = l;
      return lib;
    }
    tried += " " + path + " (entry points missing);";
  }
  failure = "the learned-model library could not be loaded:" + tried;
  throw Error(failure);
}

namespace {

std::string shippedWeights(const char* variable, const std::string& file) {
  if (const char* e = std::getenv(variable)) return e;
  std::vector<std::string> c;
  try {
    c.push_back(directoryOf(learnLibrary().path) + "/Resources/models/" + file);
  } catch (const Error&) {
  }
  c.push_back(thisModuleDirectory() + "/Resources/models/" + file);
#ifdef HOLEFILL_SOURCE_DIR
  c.push_back(std::string(HOLEFILL_SOURCE_DIR) + "/Resources/models/" + file);
#endif
  for (const auto& p : c)
    if (fileExists(p)) return p;
  return "";
}

}  // namespace

std::string defaultUvtranWeights() { return shippedWeights("HOLEFILL_UVTRAN_WEIGHTS", "uvtran.pt"); }

std::string defaultBidgcnWeights() { return shippedWeights("HOLEFILL_BIDGCN_WEIGHTS", "bidgcn.pt"); }

}  // namespace holefill::learn

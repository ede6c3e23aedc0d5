// The learned models live in a separate shared library (libholefill_learn.so, the only code
// linked to libtorch), loaded on first use: FreeCAD and the CLI start without paying libtorch's
// 0.6 s (warm) to 20 s (cold) load time, and a missing or broken library is a clear error with a
// fallback instead of a crash. Its entry points are plain C, so nothing else sees torch types.
#pragma once

#include <string>

extern "C" {
// Predicts the projection surfaces of `batch` canonical boundaries (n points each, xyz
// interleaved): writes per boundary 64 poles (xyz, row-major i*8+j, i along u) and 8 interior
// knots (4 u then 4 v). Returns 0, or non-zero with a message in err.
typedef int (*HoleFillUvtranPredictFn)(const char* weights, const double* points, int batch, int n, int threads,
                                       double* poles, double* knots, char* err, int errLen);
// BIDGCN parameters of a cloud's interior points (bidgcn.md sec. 4): n points (xyz interleaved)
// already scaled into the unit cube, boundary[k] != 0 for points whose (u, v) in [0, 1]^2 is given
// in uv (2 per point); writes (u, v) for the others into uv. Returns 0, or non-zero with a message.
typedef int (*HoleFillBidgcnPredictFn)(const char* weights, const double* points, const unsigned char* boundary, int n,
                                       int threads, double* uv, char* err, int errLen);
// `holefill train uvtran|bidgcn ...` and `holefill eval uvtran ...`: argv[0] is the verb.
typedef int (*HoleFillLearnMainFn)(int argc, char** argv);
typedef const char* (*HoleFillLearnInfoFn)();
}

namespace holefill::learn {

struct LearnLibrary {
  std::string path;
  HoleFillUvtranPredictFn predict = nullptr;
  HoleFillBidgcnPredictFn bidgcnPredict = nullptr;
  HoleFillLearnMainFn main = nullptr;
  HoleFillLearnInfoFn info = nullptr;
};

// Loads the library once per process: $HOLEFILL_LEARN_LIBRARY, else next to the binary or module
// holding this code, else the build tree. Throws holefill::Error saying where it looked and why.
const LearnLibrary& learnLibrary();

// The shipped UVTran weights: $HOLEFILL_UVTRAN_WEIGHTS, else Resources/models/uvtran.pt next to
// the loaded library, else in the source tree. Empty when none exists.
std::string defaultUvtranWeights();

// The shipped BIDGCN weights: $HOLEFILL_BIDGCN_WEIGHTS, else Resources/models/bidgcn.pt, looked
// for as the UVTran weights are. Empty when none exists.
std::string defaultBidgcnWeights();

}  // namespace holefill::learn

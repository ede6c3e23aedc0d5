// The C entry points of libholefill_learn.so (declared in learn/learn_library.h) and the
// backend check. Exceptions never cross them: every failure becomes a return code and a message.
#include <dlfcn.h>
#include <malloc.h>
#include <sys/stat.h>

#include <cstring>
#include <map>
#include <mutex>
#include <string>

#include "geometry/error.h"
#include "learn/learn_library.h"
#include "learn/torch/bidgcn_net.h"
#include "learn/torch/bidgcn_training.h"
#include "learn/torch/learn_backend.h"
#include "learn/torch/uvtran_net.h"
#include "learn/torch/uvtran_training.h"
#include <torch/version.h>

namespace holefill::learn {

std::string backendInfo() {
  try {
    const torch::Tensor a = torch::arange(4, torch::kFloat32);
    const float s = a.dot(a).item<float>();  // 0+1+4+9
    if (s != 14.0f) return "unavailable: libtorch returned a wrong result";
    return std::string("libtorch ") + TORCH_VERSION + " (" + std::to_string(torch::get_num_threads()) + " threads)";
  } catch (const std::exception& e) {
    return std::string("unavailable: ") + e.what();
  }
}

namespace {
// Freed tensor buffers stay in the heap for the next forward pass instead of going back to the
// kernel: on this VM every first touch of a fresh page costs ~7 µs, which made a 4 MB gather take
// 7 ms instead of 0.4 ms (measured). Process-wide, so bounded: blocks up to 64 MB, 128 MB kept.
const bool kMallocTuned = [] {
  mallopt(M_MMAP_THRESHOLD, 64 << 20);
  mallopt(M_TRIM_THRESHOLD, 128 << 20);
  return true;
}();
}  // namespace

void setLearnThreads(int threads) {
  static const auto openblas = reinterpret_cast<void (*)(int)>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
  if (openblas) openblas(1);
  if (threads > 0 && threads != torch::get_num_threads()) torch::set_num_threads(threads);  // resizing the pool is costly
}

namespace {

void setError(char* err, int len, const std::string& msg) {
  if (err && len > 0) {
    std::strncpy(err, msg.c_str(), len - 1);
    err[len - 1] = 0;
  }
}

// Loaded networks by path; reloaded when the file changes.
template <class Net>
struct Cached {
  long long mtime = 0;
  long long size = 0;
  Net net{nullptr};
};

template <class Net>
Net cachedNet(const std::string& path, const char* model, Net (*load)(const std::string&)) {
  static std::mutex m;
  static std::map<std::string, Cached<Net>> cache;
  struct stat st;
  if (::stat(path.c_str(), &st) != 0) throw Error(std::string(model) + " weights not found: " + path);
  std::lock_guard<std::mutex> lock(m);
  Cached<Net>& c = cache[path];
  if (!c.net || c.mtime != (long long)st.st_mtime || c.size != (long long)st.st_size) {
    c.net = load(path);
    c.mtime = st.st_mtime;
    c.size = st.st_size;
  }
  return c.net;
}

// --name value pairs after the verb and model; unknown names are an error.
struct Args {
  std::map<std::string, std::string> kv;
  std::string get(const std::string& k, const std::string& d) const {
    auto it = kv.find(k);
    return it == kv.end() ? d : it->second;
  }
};

Args parse(int argc, char** argv, int first, const std::vector<std::string>& known) {
  Args a;
  for (int i = first; i < argc; ++i) {
    std::string k = argv[i];
    if (k.rfind("--", 0) != 0 || i + 1 >= argc) throw Error("expected --name value, got '" + k + "'");
    k = k.substr(2);
    if (std::find(known.begin(), known.end(), k) == known.end()) throw Error("unknown option --" + k);
    a.kv[k] = argv[++i];
  }
  return a;
}

int trainMain(int argc, char** argv) {
  const Args a = parse(argc, argv, 2, {"out", "stage1-steps", "stage2-steps", "batch", "lr", "threads", "validate-every",
                                       "validation-samples", "checkpoint-minutes", "max-hours", "width", "heads",
                                       "layers", "feed-forward", "seed"});
  UvtranTrainOptions o;
  o.outDir = a.get("out", "uvtran-run");
  o.stage1Steps = std::stoi(a.get("stage1-steps", std::to_string(o.stage1Steps)));
  o.stage2Steps = std::stoi(a.get("stage2-steps", std::to_string(o.stage2Steps)));
  o.batch = std::stoi(a.get("batch", std::to_string(o.batch)));
  o.learningRate = std::stod(a.get("lr", std::to_string(o.learningRate)));
  o.threads = std::stoi(a.get("threads", std::to_string(o.threads)));
  o.validateEvery = std::stoi(a.get("validate-every", std::to_string(o.validateEvery)));
  o.validationSamples = std::stoi(a.get("validation-samples", std::to_string(o.validationSamples)));
  o.checkpointMinutes = std::stod(a.get("checkpoint-minutes", std::to_string(o.checkpointMinutes)));
  o.maxHours = std::stod(a.get("max-hours", "0"));
  o.width = std::stoi(a.get("width", std::to_string(o.width)));
  o.heads = std::stoi(a.get("heads", std::to_string(o.heads)));
  o.layers = std::stoi(a.get("layers", std::to_string(o.layers)));
  o.feedForward = std::stoi(a.get("feed-forward", std::to_string(o.feedForward)));
  o.seed = std::stoull(a.get("seed", "1"));
  return trainUvtran(o);
}

int trainBidgcnMain(int argc, char** argv) {
  const Args a = parse(argc, argv, 2, {"out", "steps", "batch", "interior", "noise", "lr", "supervision", "threads", "validate-every",
                                       "validation-clouds", "checkpoint-minutes", "max-hours", "seed", "init", "first-cloud"});
  BidgcnTrainOptions o;
  o.init = a.get("init", "");
  o.firstCloud = std::stoull(a.get("first-cloud", "0"));
  o.outDir = a.get("out", "bidgcn-run");
  o.steps = std::stoi(a.get("steps", std::to_string(o.steps)));
  o.batch = std::stoi(a.get("batch", std::to_string(o.batch)));
  o.interior = std::stoi(a.get("interior", std::to_string(o.interior)));
  o.noise = std::stod(a.get("noise", "0"));
  o.learningRate = std::stod(a.get("lr", std::to_string(o.learningRate)));
  o.supervision = std::stod(a.get("supervision", std::to_string(o.supervision)));
  o.threads = std::stoi(a.get("threads", std::to_string(o.threads)));
  o.validateEvery = std::stoi(a.get("validate-every", std::to_string(o.validateEvery)));
  o.validationClouds = std::stoi(a.get("validation-clouds", std::to_string(o.validationClouds)));
  o.checkpointMinutes = std::stod(a.get("checkpoint-minutes", std::to_string(o.checkpointMinutes)));
  o.maxHours = std::stod(a.get("max-hours", "0"));
  o.seed = std::stoull(a.get("seed", "1"));
  return trainBidgcn(o);
}

int evalBidgcnMain(int argc, char** argv) {
  const Args a = parse(argc, argv, 2, {"weights", "clouds", "interior", "noise", "split", "threads"});
  const std::string w = a.get("weights", defaultBidgcnWeights());
  const bool test = a.get("split", "test") == "test";
  const BidgcnEvaluation ev = evaluateBidgcn(w, std::stoi(a.get("clouds", "100")), std::stoi(a.get("interior", "1000")),
                                             std::stod(a.get("noise", "0")), test, std::stoi(a.get("threads", "1")));
  std::printf("{\"weights\": \"%s\", \"split\": \"%s\", \"clouds\": %d, \"median_mse\": %.6g, \"mean_mse\": %.6g, "
              "\"median_exact_mse\": %.6g, \"ms_per_cloud\": %.4g, \"parameters\": %lld}\n",
              w.c_str(), test ? "test" : "validation", ev.clouds, ev.medianMse, ev.meanMse, ev.medianExactMse,
              1e3 * ev.secondsPerCloud, ev.parameters);
  return 0;
}

int evalMain(int argc, char** argv) {
  const Args a = parse(argc, argv, 2, {"weights", "samples", "split", "window", "threads"});
  const std::string w = a.get("weights", defaultUvtranWeights());
  const bool test = a.get("split", "test") == "test";
  const UvtranEvaluation ev = evaluateUvtran(w, std::stoi(a.get("samples", "1000")), test,
                                             std::stoi(a.get("window", "2")), std::stoi(a.get("threads", "1")));
  std::printf("{\"weights\": \"%s\", \"split\": \"%s\", \"samples\": %d, \"param_error_coarse\": %.6g, "
              "\"param_error_fine\": %.6g, \"pole_error_coarse\": %.6g, \"pole_error_fine\": %.6g, "
              "\"knot_rmse\": %.6g, \"ms_per_hole\": %.4g, \"parameters\": %lld, \"mflop_per_hole\": %.2f}\n",
              w.c_str(), test ? "test" : "validation", ev.samples, ev.paramErrorCoarse, ev.paramErrorFine,
              ev.poleErrorCoarse, ev.poleErrorFine, ev.knotRmse, 1e3 * ev.secondsPerHole,
              ev.parameters, ev.flopsPerHole / 1e6);
  return 0;
}

}  // namespace
}  // namespace holefill::learn

using namespace holefill::learn;

extern "C" int holefill_uvtran_predict(const char* weights, const double* points, int batch, int n, int threads,
                                       double* poles, double* knots, char* err, int errLen) {
  try {
    if (!weights || !*weights) throw holefill::Error("no UVTran weights file given");
    UvtranNet net = cachedNet<UvtranNet>(weights, "UVTran", loadUvtran);
    if (n != net->config.points)
      throw holefill::Error("UVTran expects " + std::to_string(net->config.points) + " boundary points, got " +
                            std::to_string(n));
    if (batch < 1) throw holefill::Error("UVTran needs at least one boundary");
    for (int i = 0; i < 3 * n * batch; ++i)
      if (!std::isfinite(points[i])) throw holefill::Error("UVTran input holds NaN or infinity");
    setLearnThreads(threads);
    torch::NoGradGuard ng;
    torch::Tensor x = torch::empty({batch, n, 3});
    for (int i = 0; i < 3 * n * batch; ++i) x.data_ptr<float>()[i] = float(points[i]);
    const UvtranStage1 s1 = net->stage1(x);
    const torch::Tensor coarse = decodeVoxels(s1.coarseLogits, 0);
    const torch::Tensor fine = decodeVoxels(net->stage2(s1.features, coarse), 2).contiguous();
    const torch::Tensor k = s1.knots.contiguous();
    for (int i = 0; i < 64 * 3 * batch; ++i) poles[i] = fine.data_ptr<float>()[i];
    for (int b = 0; b < batch; ++b)
      for (int j = 0; j < 4; ++j) {
        knots[8 * b + j] = k.data_ptr<float>()[8 * b + 2 * j];
        knots[8 * b + 4 + j] = k.data_ptr<float>()[8 * b + 2 * j + 1];
      }
    return 0;
  } catch (const std::exception& e) {
    setError(err, errLen, e.what());
    return 1;
  }
}

extern "C" int holefill_bidgcn_predict(const char* weights, const double* points, const unsigned char* boundary, int n,
                                       int threads, double* uv, char* err, int errLen) {
  try {
    if (!weights || !*weights) throw holefill::Error("no BIDGCN weights file given");
    BidgcnNet net = cachedNet<BidgcnNet>(weights, "BIDGCN", loadBidgcn);
    std::vector<int> in, bd;
    for (int k = 0; k < n; ++k) (boundary[k] ? bd : in).push_back(k);
    if (bd.empty()) throw holefill::Error("BIDGCN needs boundary points with parameters");
    for (int k = 0; k < 3 * n; ++k)
      if (!std::isfinite(points[k])) throw holefill::Error("BIDGCN input holds NaN or infinity");
    for (int k : bd)
      if (!std::isfinite(uv[2 * k]) || !std::isfinite(uv[2 * k + 1])) throw holefill::Error("a BIDGCN boundary parameter is NaN or infinity");
    if (in.empty()) return 0;
    setLearnThreads(threads);
    torch::NoGradGuard ng;
    torch::Tensor xi = torch::empty({(int64_t)in.size(), 3}), xb = torch::empty({(int64_t)bd.size(), 3}),
                  ub = torch::empty({(int64_t)bd.size(), 2});
    auto I = xi.accessor<float, 2>(), B = xb.accessor<float, 2>(), U = ub.accessor<float, 2>();
    for (size_t k = 0; k < in.size(); ++k)
      for (int d = 0; d < 3; ++d) I[k][d] = float(points[3 * in[k] + d]);
    for (size_t k = 0; k < bd.size(); ++k) {
      for (int d = 0; d < 3; ++d) B[k][d] = float(points[3 * bd[k] + d]);
      for (int d = 0; d < 2; ++d) U[k][d] = float(uv[2 * bd[k] + d]);
    }
    const torch::Tensor out = net->forward(xi, xb, ub).contiguous();
    const auto O = out.accessor<float, 2>();
    for (size_t k = 0; k < in.size(); ++k)
      for (int d = 0; d < 2; ++d) uv[2 * in[k] + d] = O[k][d];
    return 0;
  } catch (const std::exception& e) {
    setError(err, errLen, e.what());
    return 1;
  }
}

extern "C" int holefill_learn_main(int argc, char** argv) {
  try {
    if (argc < 2) throw holefill::Error("usage: holefill train uvtran|bidgcn [--out DIR ...] | holefill eval uvtran|bidgcn [--weights W ...]");
    const std::string verb = argv[0], model = argv[1];
    if (model != "uvtran" && model != "bidgcn") throw holefill::Error("unknown model '" + model + "': use uvtran or bidgcn");
    if (verb == "train") return model == "uvtran" ? trainMain(argc, argv) : trainBidgcnMain(argc, argv);
    if (verb == "eval") return model == "uvtran" ? evalMain(argc, argv) : evalBidgcnMain(argc, argv);
    throw holefill::Error("unknown verb '" + verb + "'");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "holefill: error: %s\n", e.what());
    return 1;
  }
}

extern "C" const char* holefill_learn_info() {
  static std::string s = backendInfo();
  return s.c_str();
}

#include "learn/torch/learn_backend.h"
#include "learn/torch/uvtran_training.h"

#include <sys/stat.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <future>

#include "geometry/error.h"
#include "geometry/surface_projection.h"
#include "learn/torch/uvtran_net.h"
#include "learn/uvtran_data.h"

namespace holefill::learn {

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

struct Batch {
  torch::Tensor boundary;  // [B, n, 3]
  torch::Tensor poles;     // [B, 64, 3]
  torch::Tensor knots;     // [B, 4, 2]
  std::vector<UvtranSample> samples;
};

Batch makeBatch(UvtranSplit split, uint64_t first, int count, int points) {
  UvtranDataOptions opt;
  opt.canonical.samples = points;
  Batch b;
  b.boundary = torch::empty({count, points, 3});
  b.poles = torch::empty({count, 64, 3});
  b.knots = torch::empty({count, 4, 2});
  auto B = b.boundary.accessor<float, 3>();
  auto P = b.poles.accessor<float, 3>();
  auto K = b.knots.accessor<float, 3>();
  for (int s = 0; s < count; ++s) {
    UvtranSample x = makeUvtranSample(uvtranSeed(split, first + s), opt);
    for (int i = 0; i < points; ++i)
      for (int c = 0; c < 3; ++c) B[s][i][c] = float(x.boundary[i](c));
    for (int i = 0; i < 64; ++i)
      for (int c = 0; c < 3; ++c) P[s][i][c] = float(x.surface.poles(i, c));
    const auto ku = interiorKnots(x.surface.knotsU), kv = interiorKnots(x.surface.knotsV);
    for (int k = 0; k < 4; ++k) { K[s][k][0] = float(ku[k]); K[s][k][1] = float(kv[k]); }
    b.samples.push_back(std::move(x));
  }
  return b;
}

BSplineSurface surfaceFrom(const torch::Tensor& poles, const torch::Tensor& knots) {
  BSplineSurface s;
  const auto P = poles.accessor<float, 2>();
  const auto K = knots.accessor<float, 2>();
  std::vector<double> ku, kv;
  for (int k = 0; k < 4; ++k) { ku.push_back(K[k][0]); kv.push_back(K[k][1]); }
  s.knotsU = clampedCubicKnots(ku);
  s.knotsV = clampedCubicKnots(kv);
  s.poles.resize(64, 3);
  for (int i = 0; i < 64; ++i)
    for (int c = 0; c < 3; ++c) s.poles(i, c) = P[i][c];
  return s;
}

double paramError(const UvtranSample& x, const BSplineSurface& s) {
  const ProjectionResult r = projectSequence(s, x.boundary);
  double e = 0;
  for (size_t i = 0; i < r.uv.size(); ++i) e += (r.uv[i] - x.params[i]).norm();
  return e / r.uv.size();
}

struct Forward {
  UvtranStage1 s1;
  torch::Tensor coarsePoles, fineLogits;
};

Forward forward(UvtranNet& net, const torch::Tensor& boundary, bool withStage2) {
  Forward f;
  f.s1 = net->stage1(boundary);
  if (withStage2) {
    f.coarsePoles = decodeVoxels(f.s1.coarseLogits.detach(), 0);  // stage 1's own voxel centres
    f.fineLogits = net->stage2(f.s1.features, f.coarsePoles);
  }
  return f;
}

UvtranEvaluation evaluate(UvtranNet& net, UvtranSplit split, int count, int window, bool withStage2) {
  torch::NoGradGuard ng;
  net->eval();
  UvtranEvaluation ev;
  const int chunk = 64;
  for (int first = 0; first < count; first += chunk) {
    const int m = std::min(chunk, count - first);
    Batch b = makeBatch(split, first, m, net->config.points);
    Forward f = forward(net, b.boundary, withStage2);
    const torch::Tensor coarse = decodeVoxels(f.s1.coarseLogits, window);
    const torch::Tensor fine = withStage2 ? decodeVoxels(f.fineLogits, window) : coarse;
    ev.poleErrorCoarse += (coarse - b.poles).norm(2, -1).mean().item<double>() * m;
    ev.poleErrorFine += (fine - b.poles).norm(2, -1).mean().item<double>() * m;
    ev.knotRmse += (f.s1.knots - b.knots).pow(2).mean().item<double>() * m;
    for (int s = 0; s < m; ++s) {
      ev.paramErrorCoarse += paramError(b.samples[s], surfaceFrom(coarse[s], f.s1.knots[s]));
      ev.paramErrorFine += paramError(b.samples[s], surfaceFrom(fine[s], f.s1.knots[s]));
    }
  }
  ev.samples = count;
  ev.paramErrorCoarse /= count; ev.paramErrorFine /= count;
  ev.poleErrorCoarse /= count; ev.poleErrorFine /= count;
  ev.knotRmse = std::sqrt(ev.knotRmse / count);
  net->train();
  return ev;
}

double learningRate(const UvtranTrainOptions& o, int step) {
  const bool second = step >= o.stage1Steps;
  const int local = second ? step - o.stage1Steps : step;
  const int total = second ? o.stage2Steps : o.stage1Steps;
  const double peak = second ? 0.5 * o.learningRate : o.learningRate;
  const int warm = std::min(300, total / 10 + 1);
  if (local < warm) return peak * (local + 1) / warm;
  const double t = double(local - warm) / std::max(1, total - warm);
  return peak * (0.05 + 0.95 * 0.5 * (1 + std::cos(M_PI * std::min(1.0, t))));
}

bool fileExists(const std::string& p) {
  struct stat st;
  return ::stat(p.c_str(), &st) == 0;
}

}  // namespace

int trainUvtran(const UvtranTrainOptions& o) {
  HF_CHECK(!o.outDir.empty(), "training needs an output folder");
  ::mkdir(o.outDir.c_str(), 0755);
  setLearnThreads(o.threads);
  torch::manual_seed(o.seed);
  UvtranConfig cfg;
  cfg.width = o.width; cfg.heads = o.heads; cfg.layers = o.layers; cfg.feedForward = o.feedForward;
  const std::string ckptNet = o.outDir + "/checkpoint.pt", ckptOpt = o.outDir + "/checkpoint_optimizer.pt",
                    ckptState = o.outDir + "/checkpoint_state.txt", logPath = o.outDir + "/log.csv";
  const bool resume = fileExists(ckptState);
  UvtranNet net = resume ? loadUvtran(ckptNet) : UvtranNet(cfg);
  net->train();
  torch::optim::AdamW opt(net->parameters(), torch::optim::AdamWOptions(o.learningRate).weight_decay(1e-4));
  int step = 0;
  double wallBefore = 0;
  if (resume) {
    torch::load(opt, ckptOpt);
    std::ifstream(ckptState) >> step >> wallBefore;
    std::printf("[uvtran] resumed at step %d (%.2f h trained)\n", step, wallBefore / 3600);
  } else {
    std::ofstream(logPath) << "step,stage,lr,loss,coarse_ce,knot_mse,fine_ce,val_param_coarse,val_param_fine,"
                              "val_pole_coarse,val_pole_fine,val_knot_rmse,hours\n";
  }
  std::printf("[uvtran] %lld parameters, %.1f MFLOP per hole, %d threads\n", (long long)net->parameterCount(),
              net->flopsPerHole() / 1e6, o.threads);
  std::fflush(stdout);
  const int total = o.stage1Steps + o.stage2Steps;
  const auto t0 = Clock::now();
  auto lastCkpt = Clock::now();
  auto save = [&] {
    saveUvtran(net, ckptNet);
    torch::save(opt, ckptOpt + ".tmp");
    std::rename((ckptOpt + ".tmp").c_str(), ckptOpt.c_str());
    std::ofstream(ckptState + ".tmp") << step << " " << wallBefore + since(t0) << "\n";
    std::rename((ckptState + ".tmp").c_str(), ckptState.c_str());
    lastCkpt = Clock::now();
  };
  auto next = std::async(std::launch::async, makeBatch, UvtranSplit::Train, uint64_t(step) * o.batch, o.batch, cfg.points);
  double runLoss = 0, runC = 0, runK = 0, runF = 0;
  int runN = 0;
  net->train();
  while (step < total) {
    Batch b = next.get();
    if (step + 1 < total)
      next = std::async(std::launch::async, makeBatch, UvtranSplit::Train, uint64_t(step + 1) * o.batch, o.batch, cfg.points);
    const bool stage2 = step >= o.stage1Steps;
    for (auto& g : opt.param_groups()) static_cast<torch::optim::AdamWOptions&>(g.options()).lr(learningRate(o, step));
    Forward f = forward(net, b.boundary, stage2);
    const torch::Tensor ce1 = voxelLoss(f.s1.coarseLogits, voxelTargets(b.poles, cfg.coarse), o.sigmaCoarse);
    const torch::Tensor km = torch::mse_loss(f.s1.knots, b.knots);
    torch::Tensor loss = ce1 + km;
    torch::Tensor ce2;
    if (stage2) {
      ce2 = voxelLoss(f.fineLogits, voxelTargets(b.poles, cfg.fine), o.sigmaFine);
      loss = loss + ce2;
    }
    opt.zero_grad();
    loss.backward();
    torch::nn::utils::clip_grad_norm_(net->parameters(), 1.0);
    opt.step();
    ++step;
    runLoss += loss.item<double>(); runC += ce1.item<double>(); runK += km.item<double>();
    runF += stage2 ? ce2.item<double>() : 0.0;
    ++runN;
    const bool last = step == total;
    if (step % o.validateEvery == 0 || last) {
      const UvtranEvaluation ev = evaluate(net, UvtranSplit::Validation, o.validationSamples, o.decodeWindow, stage2);
      const double hours = (wallBefore + since(t0)) / 3600;
      std::ofstream(logPath, std::ios::app) << step << "," << (stage2 ? 2 : 1) << "," << learningRate(o, step - 1) << ","
          << runLoss / runN << "," << runC / runN << "," << runK / runN << "," << runF / runN << ","
          << ev.paramErrorCoarse << "," << ev.paramErrorFine << "," << ev.poleErrorCoarse << "," << ev.poleErrorFine
          << "," << ev.knotRmse << "," << hours << "\n";
      std::printf("[uvtran] step %d/%d stage %d loss %.4f (coarse %.4f knot %.5f fine %.4f) val param %.4g/%.4g "
                  "pole %.4g/%.4g  %.2f h\n", step, total, stage2 ? 2 : 1, runLoss / runN, runC / runN, runK / runN,
                  runF / runN, ev.paramErrorCoarse, ev.paramErrorFine, ev.poleErrorCoarse, ev.poleErrorFine, hours);
      std::fflush(stdout);
      runLoss = runC = runK = runF = 0;
      runN = 0;
    }
    const bool outOfTime = o.maxHours > 0 && wallBefore + since(t0) > o.maxHours * 3600;
    if (last || outOfTime || since(lastCkpt) > 60 * o.checkpointMinutes) save();
    if (outOfTime && !last) {
      std::printf("[uvtran] stopped at step %d after %.2f h; run again to resume\n", step, o.maxHours);
      return 3;
    }
  }
  const double hours = (wallBefore + since(t0)) / 3600;
  char card[512];
  std::snprintf(card, sizeof card,
                "UVTran width %d heads %d layers %d ff %d; stage1 %d + stage2 %d steps of batch %d; %.2f h on %d threads",
                cfg.width, cfg.heads, cfg.layers, cfg.feedForward, o.stage1Steps, o.stage2Steps, o.batch, hours,
                o.threads);
  saveUvtran(net, o.outDir + "/uvtran.pt", card);
  std::printf("[uvtran] done: %s/uvtran.pt\n", o.outDir.c_str());
  return 0;
}

UvtranEvaluation evaluateUvtran(const std::string& weights, int count, bool test, int window, int threads) {
  setLearnThreads(threads);
  UvtranNet net = loadUvtran(weights);
  UvtranEvaluation ev = evaluate(net, test ? UvtranSplit::Test : UvtranSplit::Validation, count, window, true);
  // Inference time of one hole through both stages (no batching, as in a fill).
  torch::NoGradGuard ng;
  net->eval();
  Batch b = makeBatch(UvtranSplit::Validation, 0, 1, net->config.points);
  forward(net, b.boundary, true);  // warm-up
  const int reps = 20;
  const auto t = Clock::now();
  for (int i = 0; i < reps; ++i) {
    Forward f = forward(net, b.boundary, true);
    decodeVoxels(f.fineLogits, window);
  }
  ev.secondsPerHole = since(t) / reps;
  ev.parameters = net->parameterCount();
  ev.flopsPerHole = net->flopsPerHole();
  return ev;
}

}  // namespace holefill::learn

#include "learn/torch/learn_backend.h"
#include "learn/torch/bidgcn_training.h"

#include <sys/stat.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <future>
#include <random>

#include "geometry/error.h"
#include "learn/patch_cloud.h"
#include "learn/torch/bidgcn_net.h"

namespace holefill::learn {

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

struct Cloud {
  torch::Tensor interior, boundary, boundaryUV, interiorUV;  // [nI, 3], [nB, 3], [nB, 2], exact [nI, 2]
  PatchCloud cloud;
};
using Batch = std::vector<Cloud>;

Batch makeBatch(PatchCloudSplit split, uint64_t first, int count, int interior, int boundary, double noise, bool drawNoise) {
  Batch batch;
  for (int s = 0; s < count; ++s) {
    const uint64_t seed = patchCloudSeed(split, first + s);
    PatchCloudOptions o;
    o.interior = interior;
    o.boundary = boundary;
    o.sigma = noise;
    if (drawNoise) {
      std::mt19937_64 r(seed ^ 0x9e3779b97f4a7c15ull);
      o.sigma = std::uniform_real_distribution<double>(0, noise)(r);
    }
    Cloud c;
    c.cloud = randomPatchCloud(seed, o);
    const Eigen::Matrix<float, Eigen::Dynamic, 3, Eigen::RowMajor> p = c.cloud.points.cast<float>();
    const Eigen::Matrix<float, Eigen::Dynamic, 2, Eigen::RowMajor> uv = c.cloud.uv.topRows(boundary).cast<float>();
    c.boundary = torch::from_blob((void*)p.data(), {boundary, 3}).clone();
    c.interior = torch::from_blob((void*)(p.data() + 3 * boundary), {interior, 3}).clone();
    c.boundaryUV = torch::from_blob((void*)uv.data(), {boundary, 2}).clone();
    const Eigen::Matrix<float, Eigen::Dynamic, 2, Eigen::RowMajor> exact = c.cloud.uv.bottomRows(interior).cast<float>();
    c.interiorUV = torch::from_blob((void*)exact.data(), {interior, 2}).clone();
    batch.push_back(std::move(c));
  }
  return batch;
}

Eigen::MatrixX2d predictedUV(const PatchCloud& c, const torch::Tensor& interiorUV, int boundary) {
  Eigen::MatrixX2d uv = c.uv;
  const auto A = interiorUV.accessor<float, 2>();
  for (int k = 0; k + boundary < uv.rows(); ++k) uv.row(boundary + k) << A[k][0], A[k][1];
  return uv;
}

double median(std::vector<double> v) {
  if (v.empty()) return std::nan("");
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

struct Validation {
  double median = 0, mean = 0, exact = 0;
};

Validation validate(BidgcnNet& net, PatchCloudSplit split, int count, int interior, int boundary, double noise) {
  torch::NoGradGuard ng;
  std::vector<double> mse, exact;
  for (int s = 0; s < count; ++s) {
    const Cloud b = makeBatch(split, s, 1, interior, boundary, noise, false)[0];
    const torch::Tensor uv = net->forward(b.interior, b.boundary, b.boundaryUV);
    const PatchCloud& c = b.cloud;
    mse.push_back(bezierFitMse(c.points, predictedUV(c, uv, boundary)));
    exact.push_back(bezierFitMse(c.points, c.uv));
  }
  Validation v;
  v.median = median(mse);
  for (double x : mse) v.mean += x / mse.size();
  v.exact = median(exact);
  return v;
}

double learningRate(const BidgcnTrainOptions& o, int step) {
  const int warm = std::min(500, o.steps / 10 + 1);
  if (step < warm) return o.learningRate * (step + 1) / warm;
  const double t = double(step - warm) / std::max(1, o.steps - warm);
  return o.learningRate * (0.05 + 0.95 * 0.5 * (1 + std::cos(M_PI * std::min(1.0, t))));
}

bool fileExists(const std::string& p) {
  struct stat st;
  return ::stat(p.c_str(), &st) == 0;
}

}  // namespace

int trainBidgcn(const BidgcnTrainOptions& o) {
  HF_CHECK(!o.outDir.empty(), "training needs an output folder");
  HF_CHECK(o.steps > 0 && o.batch > 0 && o.interior >= 10 && o.boundary >= 4, "training needs steps, a batch and clouds of at least 10 interior and 4 boundary points");
  ::mkdir(o.outDir.c_str(), 0755);
  setLearnThreads(o.threads);
  torch::manual_seed(o.seed);
  const std::string ckptNet = o.outDir + "/checkpoint.pt", ckptOpt = o.outDir + "/checkpoint_optimizer.pt",
                    ckptState = o.outDir + "/checkpoint_state.txt", logPath = o.outDir + "/log.csv";
  const bool resume = fileExists(ckptState);
  BidgcnNet net = resume ? loadBidgcn(ckptNet) : !o.init.empty() ? loadBidgcn(o.init) : BidgcnNet(BidgcnConfig{});
  if (!resume && !o.init.empty()) std::printf("[bidgcn] starting from %s\n", o.init.c_str());
  net->train();
  torch::optim::Adam opt(net->parameters(), torch::optim::AdamOptions(o.learningRate));
  int step = 0;
  double wallBefore = 0;
  if (resume) {
    torch::load(opt, ckptOpt);
    std::ifstream(ckptState) >> step >> wallBefore;
    std::printf("[bidgcn] resumed at step %d (%.2f h trained)\n", step, wallBefore / 3600);
  } else {
    std::ofstream(logPath) << "step,lr,loss,val_median_mse,val_mean_mse,val_exact_mse,hours\n";
  }
  std::printf("[bidgcn] %lld parameters, batch %d of %d+%d points, %d threads\n", (long long)net->parameterCount(), o.batch,
              o.interior, o.boundary, o.threads);
  std::fflush(stdout);
  const auto t0 = Clock::now();
  auto lastCkpt = Clock::now();
  auto save = [&] {
    saveBidgcn(net, ckptNet);
    torch::save(opt, ckptOpt + ".tmp");
    std::rename((ckptOpt + ".tmp").c_str(), ckptOpt.c_str());
    std::ofstream(ckptState + ".tmp") << step << " " << wallBefore + since(t0) << "\n";
    std::rename((ckptState + ".tmp").c_str(), ckptState.c_str());
    lastCkpt = Clock::now();
  };
  auto batchAt = [&](int s) {
    return std::async(std::launch::async, makeBatch, PatchCloudSplit::Train, o.firstCloud + uint64_t(s) * o.batch, o.batch, o.interior, o.boundary,
                      o.noise, o.noise > 0);
  };
  auto next = batchAt(step);
  double runLoss = 0;
  int runN = 0;
  while (step < o.steps) {
    Batch b = next.get();
    if (step + 1 < o.steps) next = batchAt(step + 1);
    for (auto& g : opt.param_groups()) static_cast<torch::optim::AdamOptions&>(g.options()).lr(learningRate(o, step));
    torch::Tensor loss = torch::zeros({}, torch::kDouble);
    for (const Cloud& c : b) {
      const torch::Tensor uv = net->forward(c.interior, c.boundary, c.boundaryUV);
      torch::Tensor l = bezierFitLoss(uv, c.interior, c.boundary, c.boundaryUV);
      if (o.supervision > 0) l = l + o.supervision * (uv - c.interiorUV).pow(2).sum(-1).mean().to(torch::kDouble);
      loss = loss + l / double(b.size());
    }
    opt.zero_grad();
    loss.backward();
    torch::nn::utils::clip_grad_norm_(net->parameters(), 1.0);
    opt.step();
    ++step;
    runLoss += loss.item<double>();
    ++runN;
    const bool last = step == o.steps;
    if (step % o.validateEvery == 0 || last) {
      const Validation v = validate(net, PatchCloudSplit::Validation, o.validationClouds, o.interior, o.boundary, 0);
      const double hours = (wallBefore + since(t0)) / 3600;
      std::ofstream(logPath, std::ios::app) << step << "," << learningRate(o, step - 1) << "," << runLoss / runN << ","
                                            << v.median << "," << v.mean << "," << v.exact << "," << hours << "\n";
      std::printf("[bidgcn] step %d/%d loss %.4g val median %.4g mean %.4g  %.2f h\n", step, o.steps, runLoss / runN, v.median,
                  v.mean, hours);
      std::fflush(stdout);
      runLoss = 0;
      runN = 0;
    }
    const bool outOfTime = o.maxHours > 0 && wallBefore + since(t0) > o.maxHours * 3600;
    if (last || outOfTime || since(lastCkpt) > 60 * o.checkpointMinutes) save();
    if (outOfTime && !last) {
      std::printf("[bidgcn] stopped at step %d after %.2f h; run again to resume\n", step, o.maxHours);
      return 3;
    }
  }
  const double hours = (wallBefore + since(t0)) / 3600;
  char card[512];
  std::snprintf(card, sizeof card, "BIDGCN radius %.3g, %d neighbours max; %d steps of %d clouds (%d+%d points, noise <= %g), "
                "supervision %g, lr %g; %.2f h on %d threads",
                net->config.radius, net->config.maxNeighbours, o.steps, o.batch, o.interior, o.boundary, o.noise, o.supervision,
                o.learningRate, hours, o.threads);
  saveBidgcn(net, o.outDir + "/bidgcn.pt", card);
  std::printf("[bidgcn] done: %s/bidgcn.pt\n", o.outDir.c_str());
  return 0;
}

BidgcnEvaluation evaluateBidgcn(const std::string& weights, int clouds, int interior, double noise, bool test, int threads) {
  HF_CHECK(clouds > 0 && interior >= 10, "evaluation needs clouds of at least 10 interior points");
  setLearnThreads(threads);
  BidgcnNet net = loadBidgcn(weights);
  const PatchCloudSplit split = test ? PatchCloudSplit::Test : PatchCloudSplit::Validation;
  const Validation v = validate(net, split, clouds, interior, 34, noise);
  BidgcnEvaluation ev;
  ev.clouds = clouds;
  ev.medianMse = v.median;
  ev.meanMse = v.mean;
  ev.medianExactMse = v.exact;
  torch::NoGradGuard ng;
  const Cloud b = makeBatch(split, 0, 1, interior, 34, noise, false)[0];
  net->forward(b.interior, b.boundary, b.boundaryUV);  // warm-up
  std::vector<double> s;
  for (int i = 0; i < 10; ++i) {
    const auto t = Clock::now();
    net->forward(b.interior, b.boundary, b.boundaryUV);
    s.push_back(since(t));
  }
  ev.secondsPerCloud = median(s);
  ev.parameters = net->parameterCount();
  return ev;
}

}  // namespace holefill::learn

// Training and evaluation of the BIDGCN parameterization network on the synthetic clouds of
// patch_cloud.h (bidgcn.md sec. 4.2-4.4), on CPU: unsupervised, the loss is the biquadratic
// least-squares residual at the predicted parameters. The paper's 100,000 stored clouds become an
// endless stream from disjoint seeds (never the validation or test seeds), so a run is
// reproducible and resumes from its checkpoint at any step. Two departures, both for a 2-core
// budget (the paper trained 100,000 clouds on a GPU): Adam with warm-up and cosine decay instead
// of SGD at 0.1 with plateau decay, and the synthetic clouds' exact interior parameters added to
// the loss as a supervised term (mean |u − u_exact|², weight `supervision`). The exact
// parameters are the unsupervised loss's own minimum (zero residual, unique for a generic patch),
// so the term points at the same answer but gives every point a gradient from the first step:
// measured on the first 500 steps, unsupervised alone reached a validation median of 1.5e-2.
// Torch-free header.
#pragma once

#include <string>

namespace holefill::learn {

struct BidgcnTrainOptions {
  std::string outDir;             // checkpoint, log.csv and bidgcn.pt go here
  int steps = 20000;
  int batch = 4;                  // clouds per step
  int interior = 1000, boundary = 34;
  double noise = 0;               // Gaussian σ drawn uniformly in [0, noise] per training cloud
  double learningRate = 1e-3;     // Adam, linear warm-up then cosine decay to 5%
  double supervision = 1.0;       // weight of the exact-parameter term (0: the paper's loss alone)
  int threads = 2;
  int validateEvery = 500;        // steps
  int validationClouds = 64;      // fixed validation seeds
  double checkpointMinutes = 5;
  double maxHours = 0;            // > 0: checkpoint and stop after this much wall time (resume later)
  unsigned long long seed = 1;    // parameter initialization
  std::string init;               // without a checkpoint: start from these weights (fine-tuning), not at random
  unsigned long long firstCloud = 0;  // index of the first training cloud: a fine-tuning run past the
                                      // clouds its init already saw gets fresh data, not a repeat
};

int trainBidgcn(const BidgcnTrainOptions& options);  // 0 when finished, 3 when stopped by maxHours

struct BidgcnEvaluation {
  int clouds = 0;
  double medianMse = 0, meanMse = 0;     // biquadratic fit at the predicted parameters (patch_cloud.h)
  double medianExactMse = 0;             // ... at the exact parameters (the floor; > 0 only with noise)
  double secondsPerCloud = 0;            // median forward pass, batch of one
  long long parameters = 0;
};

BidgcnEvaluation evaluateBidgcn(const std::string& weights, int clouds, int interior, double noise, bool test, int threads);

}  // namespace holefill::learn

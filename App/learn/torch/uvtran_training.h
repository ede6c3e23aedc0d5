// Training and evaluation of UVTran on the synthetic data of uvtran_data.h, on CPU, with the
// paper's progressive resolution (uvtran.md Sec. 4.4): stage 1 alone first (coarse voxels and
// knots), then both stages, stage 2 fed with stage 1's own decoded predictions so that it learns
// to correct their discretization error. Batches are drawn from disjoint seed ranges, so the
// run is reproducible and resumable from a checkpoint at any step. Torch-free header.
#pragma once

#include <string>

namespace holefill::learn {

struct UvtranTrainOptions {
  std::string outDir;             // checkpoint, log.csv and uvtran.pt go here
  int stage1Steps = 2500;         // coarse stage alone
  int stage2Steps = 3000;         // both stages
  int batch = 32;
  double learningRate = 1e-3;     // AdamW, linear warm-up then cosine decay per stage
  int threads = 2;
  int validateEvery = 500;        // steps
  int validationSamples = 256;    // fixed validation seeds
  double checkpointMinutes = 5;
  double maxHours = 0;            // > 0: checkpoint and stop after this much wall time (resume later)
  double sigmaCoarse = 0.5, sigmaFine = 1.0;  // label spread in classes (0: one-hot cross-entropy)
  int width = 128, heads = 4, layers = 2, feedForward = 256;
  int decodeWindow = 2;           // classes around the arg-max averaged when decoding
  unsigned long long seed = 1;    // parameter initialization
};

int trainUvtran(const UvtranTrainOptions& options);  // 0 when finished, 3 when stopped by maxHours

struct UvtranEvaluation {
  int samples = 0;
  double paramErrorCoarse = 0, paramErrorFine = 0;  // mean |uv - uv_true| over all boundary points
  double poleErrorCoarse = 0, poleErrorFine = 0;    // mean pole distance (canonical units)
  double knotRmse = 0;
  double secondsPerHole = 0;                        // forward pass of both stages, batch of one
  long long parameters = 0;
  double flopsPerHole = 0;
};

// On `count` samples of the validation (test = false) or test split.
UvtranEvaluation evaluateUvtran(const std::string& weights, int count, bool test, int decodeWindow, int threads);

}  // namespace holefill::learn

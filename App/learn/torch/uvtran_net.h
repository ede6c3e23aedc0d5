// The UVTran network (uvtran.md Sec. 4, Fig. 3) in libtorch. Stage 1: a PointNet embeds the
// ordered boundary points; linear maps over the point axis make 64 control-point tokens and 4
// knot tokens; two Transformer encoders; heads give per-axis voxel logits of the 64 poles at
// dv = 1/coarse and the 4 interior knots of u and v. Stage 2: the decoded stage-1 poles are
// embedded by a second PointNet, attend to the boundary features (cross-attention: queries are
// poles, keys/values boundary points), are concatenated with their own features, pass a third
// encoder and a head gives per-axis logits at dv = 1/fine. Included only by the torch TUs.
#pragma once

#include <torch/torch.h>

#include <string>

namespace holefill::learn {

struct UvtranConfig {
  int points = 128;  // boundary samples in
  int width = 128;   // token width d
  int heads = 4;
  int layers = 2;    // per encoder
  int feedForward = 256;
  int coarse = 10;   // voxel classes per axis, stage 1 (dv = 0.1)
  int fine = 100;    // stage 2 (dv = 0.01)
  double dropout = 0.05;
  std::vector<int64_t> toVector() const { return {points, width, heads, layers, feedForward, coarse, fine}; }
  static UvtranConfig fromVector(const std::vector<int64_t>& v);
};

struct PointNetImpl : torch::nn::Module {
  explicit PointNetImpl(int width);
  torch::Tensor forward(const torch::Tensor& x);  // [B, n, 3] -> [B, n, width]
  torch::nn::Linear a{nullptr}, b{nullptr}, c{nullptr};
};
TORCH_MODULE(PointNet);

struct UvtranStage1 {
  torch::Tensor coarseLogits;  // [B, 64, 3, coarse]
  torch::Tensor knots;         // [B, 4, 2]: interior knots of u (col 0) and v (col 1), in (0, 1)
  torch::Tensor features;      // [B, n, width] boundary features for stage 2
};

struct UvtranNetImpl : torch::nn::Module {
  explicit UvtranNetImpl(const UvtranConfig& config);
  UvtranStage1 stage1(const torch::Tensor& boundary);  // [B, n, 3] canonical coordinates
  torch::Tensor stage2(const torch::Tensor& features, const torch::Tensor& coarsePoles);  // -> [B, 64, 3, fine]
  int64_t parameterCount() const;
  double flopsPerHole() const;  // multiply-adds x 2 of one forward pass through both stages

  UvtranConfig config;
  PointNet boundaryNet{nullptr}, poleNet{nullptr};
  torch::nn::Linear poleTokens{nullptr}, knotTokens{nullptr}, fuse{nullptr};
  torch::Tensor poleEmbedding, knotEmbedding, fineEmbedding;
  torch::nn::TransformerEncoder poleEncoder{nullptr}, knotEncoder{nullptr}, fineEncoder{nullptr};
  torch::nn::MultiheadAttention cross{nullptr};
  torch::nn::Sequential coarseHead{nullptr}, knotHead{nullptr}, fineHead{nullptr};
};
TORCH_MODULE(UvtranNet);

// Voxel centres of the arg-max class ([B, 64, 3, V] logits -> [B, 64, 3] in [0, 1]). With
// `window` > 0 the centre is the probability-weighted mean of the 2*window+1 classes around the
// arg-max, which resolves positions between centres.
torch::Tensor decodeVoxels(const torch::Tensor& logits, int window = 0);

// Per-axis class indices of coordinates in [0, 1] ([B, 64, 3] -> long).
torch::Tensor voxelTargets(const torch::Tensor& coords, int classes);

// Cross-entropy against labels spread as a Gaussian of `sigma` classes (0: one-hot).
torch::Tensor voxelLoss(const torch::Tensor& logits, const torch::Tensor& targets, double sigma);

// Weight files: a torch archive holding a format tag, the config and the parameters; loading
// checks all three and every parameter's shape, and says what is wrong.
void saveUvtran(UvtranNet& net, const std::string& path, const std::string& card = "");
UvtranNet loadUvtran(const std::string& path);

}  // namespace holefill::learn

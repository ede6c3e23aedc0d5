// The BIDGCN parameterization network (bidgcn.md sec. 2.2, 4.1, Fig. 3) in libtorch. Input: the
// interior points x_i and the boundary points x_k with their parameters u_k, all in the unit cube.
// The boundary-informed input layer averages two edge MLPs over radius graphs built on positions:
// h(x_i, x_j − x_i) over interior neighbours (6→64→64) and g(x_i, x_k − x_i, u_k) over boundary
// neighbours (8→64→64). Four dynamic radius edge convolutions follow, each building its graph
// anew in the feature space it receives (128→64, mean). The five 64-wide outputs are concatenated
// and an MLP 320→256→256→2 with a sigmoid gives (u, v) per interior point: 192,130 parameters.
// Radius graphs keep the nearest `maxNeighbours` within the radius (the reference implementation's
// torch-cluster cap, which bounds the cost on dense clouds) and include the point itself, so no
// interior point is without a message. Batch normalization uses each cloud's own statistics in
// training and inference alike (no running averages), so a cloud's answer does not depend on
// what else is in the batch; the network takes one cloud at a time. Included only by torch TUs.
#pragma once

#include <torch/torch.h>

#include <string>

namespace holefill::learn {

struct BidgcnConfig {
  double radius = 0.1;    // of every radius graph (positions in the unit cube, then features)
  int maxNeighbours = 32;
  int width = 64;         // edge-convolution output features
  int hidden = 4;         // dynamic edge-convolution layers
  int head = 256;         // output MLP width
  std::vector<double> toVector() const { return {radius, double(maxNeighbours), double(width), double(hidden), double(head)}; }
  static BidgcnConfig fromVector(const std::vector<double>& v);
};

// The directed edges (src -> dst) from each row of `to` among the `k` nearest within `r` of each
// row of `from` ([n, C], [m, C]), and the number of edges into each `from` row ([n, 1], float).
struct RadiusGraph {
  torch::Tensor src, dst, degree;
};
RadiusGraph radiusGraph(const torch::Tensor& from, const torch::Tensor& to, double r, int k);

// Linear layers with batch normalization over the rows of one cloud (no running statistics) and
// ReLU between them, not after the last.
struct EdgeMlpImpl : torch::nn::Module {
  EdgeMlpImpl(const std::vector<int>& sizes);
  torch::Tensor forward(torch::Tensor x);  // [M, C] -> [M, out]
  // Σ over the edges (j, i) of g of the MLP at [x_i, x_j − x_i, extra_j], for a two-layer MLP:
  // the first layer is split into per-point products before the gather, and the last (linear)
  // layer is applied after the sum, which is what makes the input layer cheap. xi: [n, c];
  // xj: [m, c + extra] (positions first) -> [n, out].
  torch::Tensor sumOverEdges(const torch::Tensor& xi, const torch::Tensor& xj, const RadiusGraph& g);
  std::vector<torch::nn::Linear> linears;
  std::vector<torch::Tensor> gammas, betas;
};
TORCH_MODULE(EdgeMlp);

struct BidgcnNetImpl : torch::nn::Module {
  explicit BidgcnNetImpl(const BidgcnConfig& config = {});
  // One cloud: interior [nI, 3], boundary [nB, 3], boundaryUV [nB, 2] -> interior (u, v) [nI, 2].
  torch::Tensor forward(const torch::Tensor& interior, const torch::Tensor& boundary, const torch::Tensor& boundaryUV);
  int64_t parameterCount() const;

  BidgcnConfig config;
  EdgeMlp interiorEdges{nullptr}, boundaryEdges{nullptr}, head{nullptr};
  std::vector<torch::nn::Linear> hidden;
  std::vector<double> lastDegrees;  // mean in-degree of each graph of the last forward pass (diagnostic)
};
TORCH_MODULE(BidgcnNet);

// The training loss (sec. 4.4) of one cloud: the least-squares biquadratic Bézier fit of all
// points at the boundary's and the predicted parameters, solved by the normal equations in double
// precision (differentiable); returns the mean |S(u_k) − x_k|² over the cloud's points.
torch::Tensor bezierFitLoss(const torch::Tensor& interiorUV, const torch::Tensor& interior, const torch::Tensor& boundary,
                            const torch::Tensor& boundaryUV, int degree = 2);

void saveBidgcn(BidgcnNet& net, const std::string& path, const std::string& card = "");
BidgcnNet loadBidgcn(const std::string& path);

}  // namespace holefill::learn

#include "learn/torch/uvtran_net.h"

#include <fstream>

#include "geometry/error.h"
#include "learn/torch/weight_file.h"

namespace holefill::learn {

namespace nn = torch::nn;

namespace {
constexpr int kPoles = 64, kKnotTokens = 4;
constexpr int64_t kFormat = 20261122;  // bump when the architecture changes incompatibly

nn::TransformerEncoder encoder(const UvtranConfig& c) {
  return nn::TransformerEncoder(nn::TransformerEncoderOptions(
      nn::TransformerEncoderLayerOptions(c.width, c.heads).dim_feedforward(c.feedForward).dropout(c.dropout),
      c.layers));
}

nn::Sequential head(int width, int out) {
  return nn::Sequential(nn::Linear(width, width), nn::ReLU(), nn::Linear(width, out));
}

// [B, S, E] -> encoder over S -> [B, S, E] (libtorch 1.13 encoders are sequence-first).
torch::Tensor encode(nn::TransformerEncoder& e, const torch::Tensor& x) {
  return e->forward(x.transpose(0, 1)).transpose(0, 1);
}
}  // namespace

UvtranConfig UvtranConfig::fromVector(const std::vector<int64_t>& v) {
  if (v.size() != 7) throw Error("UVTran weights: the config record has " + std::to_string(v.size()) + " fields, not 7");
  UvtranConfig c;
  c.points = int(v[0]); c.width = int(v[1]); c.heads = int(v[2]); c.layers = int(v[3]);
  c.feedForward = int(v[4]); c.coarse = int(v[5]); c.fine = int(v[6]);
  if (c.points < 6 || c.width < 1 || c.heads < 1 || c.width % c.heads || c.layers < 1 || c.feedForward < 1 ||
      c.coarse < 2 || c.fine < 2)
    throw Error("UVTran weights: the config record is invalid");
  return c;
}

PointNetImpl::PointNetImpl(int width) {
  a = register_module("a", nn::Linear(3, 64));
  b = register_module("b", nn::Linear(64, 128));
  c = register_module("c", nn::Linear(128, width));
}

torch::Tensor PointNetImpl::forward(const torch::Tensor& x) {
  return c(torch::relu(b(torch::relu(a(x)))));
}

UvtranNetImpl::UvtranNetImpl(const UvtranConfig& cfg) : config(cfg) {
  const int d = cfg.width;
  boundaryNet = register_module("boundary_net", PointNet(d));
  poleNet = register_module("pole_net", PointNet(d));
  poleTokens = register_module("pole_tokens", nn::Linear(cfg.points, kPoles));
  knotTokens = register_module("knot_tokens", nn::Linear(cfg.points, kKnotTokens));
  poleEmbedding = register_parameter("pole_embedding", 0.02 * torch::randn({kPoles, d}));
  knotEmbedding = register_parameter("knot_embedding", 0.02 * torch::randn({kKnotTokens, d}));
  fineEmbedding = register_parameter("fine_embedding", 0.02 * torch::randn({kPoles, d}));
  poleEncoder = register_module("pole_encoder", encoder(cfg));
  knotEncoder = register_module("knot_encoder", encoder(cfg));
  fineEncoder = register_module("fine_encoder", encoder(cfg));
  cross = register_module("cross", nn::MultiheadAttention(nn::MultiheadAttentionOptions(d, cfg.heads)));
  fuse = register_module("fuse", nn::Linear(2 * d, d));
  coarseHead = register_module("coarse_head", head(d, 3 * cfg.coarse));
  knotHead = register_module("knot_head", head(d, 2));
  fineHead = register_module("fine_head", head(d, 3 * cfg.fine));
}

UvtranStage1 UvtranNetImpl::stage1(const torch::Tensor& boundary) {
  UvtranStage1 s;
  const int64_t B = boundary.size(0);
  s.features = boundaryNet(boundary - 0.5);                                  // [B, n, d]
  const torch::Tensor f = s.features.transpose(1, 2);                        // [B, d, n]
  torch::Tensor poles = poleTokens(f).transpose(1, 2) + poleEmbedding;        // [B, 64, d]
  torch::Tensor knots = knotTokens(f).transpose(1, 2) + knotEmbedding;        // [B, 4, d]
  poles = encode(poleEncoder, poles);
  knots = encode(knotEncoder, knots);
  s.coarseLogits = coarseHead->forward(poles).view({B, kPoles, 3, config.coarse});
  s.knots = torch::sigmoid(knotHead->forward(knots));                      // [B, 4, 2]
  return s;
}

torch::Tensor UvtranNetImpl::stage2(const torch::Tensor& features, const torch::Tensor& coarsePoles) {
  const int64_t B = features.size(0);
  const torch::Tensor q = poleNet(coarsePoles - 0.5) + fineEmbedding;        // [B, 64, d]
  const torch::Tensor kv = features.transpose(0, 1);                         // [n, B, d]
  const torch::Tensor w = std::get<0>(cross->forward(q.transpose(0, 1), kv, kv)).transpose(0, 1);
  torch::Tensor x = fuse(torch::cat({w, q}, -1));
  x = encode(fineEncoder, x);
  return fineHead->forward(x).view({B, kPoles, 3, config.fine});
}

int64_t UvtranNetImpl::parameterCount() const {
  int64_t n = 0;
  for (const auto& p : parameters()) n += p.numel();
  return n;
}

double UvtranNetImpl::flopsPerHole() const {
  const double n = config.points, d = config.width, ff = config.feedForward, L = config.layers;
  auto pointNet = [&](double pts) { return pts * (3 * 64 + 64 * 128 + 128 * d); };
  auto layer = [&](double S) { return S * (4 * d * d + 2 * d * ff) + 2 * S * S * d; };
  auto headCost = [&](double S, double out) { return S * (d * d + d * out); };
  double mac = pointNet(n) + (kPoles + kKnotTokens) * n * d;                 // embedding and token maps
  mac += L * (layer(kPoles) + layer(kKnotTokens));
  mac += headCost(kPoles, 3 * config.coarse) + headCost(kKnotTokens, 2);
  mac += pointNet(kPoles) + kPoles * d * d * 2 + n * d * d * 2 + 2 * kPoles * n * d;  // cross-attention
  mac += kPoles * 2 * d * d + L * layer(kPoles) + headCost(kPoles, 3 * config.fine);
  return 2 * mac;
}

torch::Tensor decodeVoxels(const torch::Tensor& logits, int window) {
  const int64_t V = logits.size(-1);
  const torch::Tensor idx = logits.argmax(-1);
  if (window <= 0) return (idx.to(torch::kFloat32) + 0.5) / double(V);
  const torch::Tensor prob = torch::softmax(logits, -1);
  const torch::Tensor classes = torch::arange(V, logits.options()).expand_as(prob);
  const torch::Tensor near = (classes - idx.unsqueeze(-1).to(logits.dtype())).abs() <= window;
  const torch::Tensor p = prob * near;
  return ((p * (classes + 0.5)).sum(-1) / p.sum(-1)) / double(V);
}

torch::Tensor voxelTargets(const torch::Tensor& coords, int classes) {
  return (coords * classes).floor().clamp(0, classes - 1).to(torch::kLong);
}

torch::Tensor voxelLoss(const torch::Tensor& logits, const torch::Tensor& targets, double sigma) {
  const int64_t V = logits.size(-1);
  const torch::Tensor logp = torch::log_softmax(logits, -1).reshape({-1, V});
  const torch::Tensor t = targets.reshape({-1});
  if (sigma <= 0) return torch::nll_loss(logp, t);
  const torch::Tensor classes = torch::arange(V, logits.options()).unsqueeze(0);
  torch::Tensor soft = torch::exp(-0.5 * (classes - t.unsqueeze(1).to(logits.dtype())).pow(2) / (sigma * sigma));
  soft = soft / soft.sum(1, true);
  return -(soft * logp).sum(1).mean();
}

void saveUvtran(UvtranNet& net, const std::string& path, const std::string& card) {
  saveWeights(*net, torch::tensor(net->config.toVector()), kFormat, card, path, "UVTran");
}

UvtranNet loadUvtran(const std::string& path) {
  torch::serialize::InputArchive a;
  const torch::Tensor cfg = openWeights(a, path, kFormat, "UVTran").to(torch::kLong).contiguous();
  UvtranNet net(UvtranConfig::fromVector(std::vector<int64_t>(cfg.data_ptr<int64_t>(), cfg.data_ptr<int64_t>() + cfg.numel())));
  loadWeights(a, *net, path, "UVTran");
  return net;
}

}  // namespace holefill::learn

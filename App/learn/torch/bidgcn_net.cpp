#include "learn/torch/bidgcn_net.h"

#include <algorithm>
#include <cstdio>

#include <ATen/Parallel.h>

#include "geometry/error.h"
#include "learn/torch/weight_file.h"

namespace holefill::learn {

namespace {
constexpr int64_t kFormat = 20261201;  // bump when the architecture changes incompatibly

torch::Tensor cloudBatchNorm(const torch::Tensor& x, const torch::Tensor& gamma, const torch::Tensor& beta) {
  return torch::batch_norm(x, gamma, beta, {}, {}, /*training=*/true, 0.0, 1e-5, false);
}

torch::Tensor sumInto(const torch::Tensor& values, const torch::Tensor& dst, int64_t n) {
  return torch::zeros({n, values.size(1)}, values.options()).index_add(0, dst, values);
}
}  // namespace

BidgcnConfig BidgcnConfig::fromVector(const std::vector<double>& v) {
  HF_CHECK(v.size() == 5, "BIDGCN config record has " + std::to_string(v.size()) + " entries, expected 5");
  BidgcnConfig c;
  c.radius = v[0];
  c.maxNeighbours = int(v[1]);
  c.width = int(v[2]);
  c.hidden = int(v[3]);
  c.head = int(v[4]);
  HF_CHECK(c.radius > 0 && c.maxNeighbours >= 1 && c.width >= 1 && c.hidden >= 0 && c.head >= 1 && c.width <= 4096 &&
               c.head <= 4096 && c.hidden <= 64 && c.maxNeighbours <= 4096,
           "BIDGCN config record is out of range");
  return c;
}

EdgeMlpImpl::EdgeMlpImpl(const std::vector<int>& sizes) {
  for (size_t l = 0; l + 1 < sizes.size(); ++l) {
    linears.push_back(register_module("linear" + std::to_string(l), torch::nn::Linear(sizes[l], sizes[l + 1])));
    if (l + 2 < sizes.size()) {
      gammas.push_back(register_parameter("norm" + std::to_string(l) + "_weight", torch::ones({sizes[l + 1]})));
      betas.push_back(register_parameter("norm" + std::to_string(l) + "_bias", torch::zeros({sizes[l + 1]})));
    }
  }
}

torch::Tensor EdgeMlpImpl::sumOverEdges(const torch::Tensor& xi, const torch::Tensor& xj, const RadiusGraph& g) {
  HF_CHECK(linears.size() == 2, "sumOverEdges needs a two-layer edge MLP");
  const int64_t c = xi.size(-1);
  const torch::Tensor W = linears[0]->weight;  // [h, 2c + extra] acting on [x_i, x_j − x_i, extra_j]
  const torch::Tensor Wi = W.narrow(1, 0, c), Wj = W.narrow(1, c, W.size(1) - c);
  const torch::Tensor own = torch::linear(xi, Wi - Wj.narrow(1, 0, c), linears[0]->bias);
  const torch::Tensor other = torch::linear(xj, Wj);
  const torch::Tensor e = torch::relu(cloudBatchNorm(own.index_select(0, g.dst) + other.index_select(0, g.src), gammas[0], betas[0]));
  return torch::linear(sumInto(e, g.dst, xi.size(0)), linears[1]->weight) + g.degree * linears[1]->bias;
}

torch::Tensor EdgeMlpImpl::forward(torch::Tensor x) {
  for (size_t l = 0; l < linears.size(); ++l) {
    x = linears[l]->forward(x);
    if (l + 1 < linears.size()) x = torch::relu(cloudBatchNorm(x, gammas[l], betas[l]));
  }
  return x;
}

RadiusGraph radiusGraph(const torch::Tensor& from, const torch::Tensor& to, double r, int k) {
  HF_CHECK(k >= 1 && to.size(0) < (int64_t(1) << 31), "a radius graph keeps at least one neighbour, of fewer than 2^31 points");
  torch::NoGradGuard ng;
  const torch::Tensor f = from.detach().to(torch::kFloat).contiguous(), t = to.detach().to(torch::kFloat).contiguous();
  const torch::Tensor fNorm = f.pow(2).sum(-1, true), tNorm = t.pow(2).sum(-1).unsqueeze(0);
  const int64_t n = f.size(0), m = t.size(0);
  const float r2 = float(r * r);
  // Per block of rows: the squared distances to all of `to` (a block stays in cache), then per row
  // the candidates within reach, compacted without branches; whenever there are more than 4k, the
  // k nearest by (distance, index) are kept and the reach shrinks to the k-th distance. That is the
  // set a scan with a bounded max-heap keeps, at a fraction of its cost on the dense feature-space
  // graphs, where a row has hundreds (and on a 20,000-point scan thousands) of candidates.
  const int64_t stride = std::min<int64_t>(k, m);  // a row's most neighbours
  std::vector<int64_t> nbr(n * stride);
  std::vector<int> count(n);
  constexpr int64_t kBlock = 64;
  at::parallel_for(0, (n + kBlock - 1) / kBlock, 1, [&](int64_t a, int64_t b) {
    std::vector<int> cand(m + 1);
    std::vector<std::pair<float, int>> best;
    for (int64_t blk = a; blk < b; ++blk) {
      const int64_t i0 = blk * kBlock, rows = std::min(kBlock, n - i0);
      const torch::Tensor d2 = torch::addmm(fNorm.narrow(0, i0, rows) + tNorm, f.narrow(0, i0, rows), t.t(), 1, -2).contiguous();
      const float* D = d2.data_ptr<float>();
      for (int64_t q = 0; q < rows; ++q) {
        const float* d = D + q * m;
        float reach = r2;  // shrinks to the k-th nearest distance once k candidates are known
        int64_t c = 0;
        const auto keepNearest = [&] {
          best.clear();
          for (int64_t e = 0; e < c; ++e) best.push_back({d[cand[e]], cand[e]});
          std::nth_element(best.begin(), best.begin() + (k - 1), best.end());
          reach = best[k - 1].first;  // anything farther is beaten by k others; ties stay in the race
          for (int e = 0; e < k; ++e) cand[e] = best[e].second;
          c = k;
        };
        for (int64_t j0 = 0; j0 < m; j0 += 256) {
          for (int64_t j = j0, j1 = std::min(m, j0 + 256); j < j1; ++j) {
            cand[c] = int(j);
            c += d[j] <= reach;
          }
          if (c > 4 * int64_t(k)) keepNearest();
        }
        if (c > k) keepNearest();
        int64_t* out = nbr.data() + (i0 + q) * stride;
        std::copy(cand.begin(), cand.begin() + c, out);
        std::sort(out, out + c);
        count[i0 + q] = int(c);
      }
    }
  });
  int64_t E = 0;
  for (int c : count) E += c;
  RadiusGraph g{torch::empty({E}, torch::kLong), torch::empty({E}, torch::kLong), torch::empty({n, 1})};
  int64_t *S = g.src.data_ptr<int64_t>(), *T = g.dst.data_ptr<int64_t>();
  float* deg = g.degree.data_ptr<float>();
  int64_t e = 0;
  for (int64_t i = 0; i < n; ++i) {
    deg[i] = float(count[i]);
    for (int q = 0; q < count[i]; ++q) S[e] = nbr[i * stride + q], T[e++] = i;
  }
  g.degree = g.degree.to(from.dtype());
  return g;
}

BidgcnNetImpl::BidgcnNetImpl(const BidgcnConfig& c) : config(c) {
  const int w = c.width;
  interiorEdges = register_module("interior_edges", EdgeMlp(std::vector<int>{6, w, w}));
  boundaryEdges = register_module("boundary_edges", EdgeMlp(std::vector<int>{8, w, w}));
  for (int l = 0; l < c.hidden; ++l)
    hidden.push_back(register_module("hidden" + std::to_string(l), torch::nn::Linear(2 * w, w)));
  head = register_module("head", EdgeMlp(std::vector<int>{w * (c.hidden + 1), c.head, c.head, 2}));
}

torch::Tensor BidgcnNetImpl::forward(const torch::Tensor& interior, const torch::Tensor& boundary, const torch::Tensor& boundaryUV) {
  const double r = config.radius;
  const int K = config.maxNeighbours;
  const int64_t n = interior.size(0);
  lastDegrees.clear();
  // Input layer: messages from interior and boundary neighbours, averaged together.
  const RadiusGraph gI = radiusGraph(interior, interior, r, K), gB = radiusGraph(interior, boundary, r, K);
  lastDegrees.push_back(gI.degree.mean().item<double>());
  lastDegrees.push_back(gB.degree.mean().item<double>());
  torch::Tensor x = torch::relu((interiorEdges->sumOverEdges(interior, interior, gI) +
                                 boundaryEdges->sumOverEdges(interior, torch::cat({boundary, boundaryUV}, -1), gB)) /
                                (gI.degree + gB.degree));  // ≥ 1: the point itself is its neighbour
  std::vector<torch::Tensor> outs{x};
  // Dynamic edge convolutions: the graph is rebuilt in the features each layer receives. Their
  // MLP is one linear map, so the mean of h(x_i, x_j − x_i) is h(x_i, mean_j x_j − x_i).
  for (auto& layer : hidden) {
    const RadiusGraph g = radiusGraph(x, x, r, K);
    lastDegrees.push_back(g.degree.mean().item<double>());
    const torch::Tensor mean = sumInto(x.index_select(0, g.src), g.dst, n) / g.degree;
    x = torch::relu(layer->forward(torch::cat({x, mean - x}, -1)));
    outs.push_back(x);
  }
  return torch::sigmoid(head->forward(torch::cat(outs, -1)));
}

int64_t BidgcnNetImpl::parameterCount() const {
  int64_t n = 0;
  for (const auto& p : parameters()) n += p.numel();
  return n;
}

torch::Tensor bezierFitLoss(const torch::Tensor& interiorUV, const torch::Tensor& interior, const torch::Tensor& boundary,
                            const torch::Tensor& boundaryUV, int degree) {
  const torch::Tensor uv = torch::cat({boundaryUV, interiorUV}, 0).to(torch::kDouble);
  const torch::Tensor p = torch::cat({boundary, interior}, 0).to(torch::kDouble);
  const auto basis = [&](const torch::Tensor& t) {  // [N] -> [N, degree + 1]
    std::vector<torch::Tensor> b;
    for (int i = 0; i <= degree; ++i) {
      double binom = 1;
      for (int k = 1; k <= i; ++k) binom = binom * (degree - k + 1) / k;
      b.push_back(binom * t.pow(i) * (1 - t).pow(degree - i));
    }
    return torch::stack(b, -1);
  };
  const int64_t N = uv.size(0), m = degree + 1;
  const torch::Tensor A = (basis(uv.select(-1, 0)).unsqueeze(-1) * basis(uv.select(-1, 1)).unsqueeze(-2)).reshape({N, m * m});
  const torch::Tensor AtA = torch::mm(A.t(), A) + 1e-12 * torch::eye(m * m, A.options());
  const torch::Tensor c = torch::linalg_solve(AtA, torch::mm(A.t(), p));
  return (torch::mm(A, c) - p).pow(2).sum(-1).mean();
}

void saveBidgcn(BidgcnNet& net, const std::string& path, const std::string& card) {
  saveWeights(*net, torch::tensor(net->config.toVector(), torch::kDouble), kFormat, card, path, "BIDGCN");
}

BidgcnNet loadBidgcn(const std::string& path) {
  torch::serialize::InputArchive a;
  const torch::Tensor cfg = openWeights(a, path, kFormat, "BIDGCN").to(torch::kDouble).contiguous();
  BidgcnNet net(BidgcnConfig::fromVector(std::vector<double>(cfg.data_ptr<double>(), cfg.data_ptr<double>() + cfg.numel())));
  loadWeights(a, *net, path, "BIDGCN");
  return net;
}

}  // namespace holefill::learn

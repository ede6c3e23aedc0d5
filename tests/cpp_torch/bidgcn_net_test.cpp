// The BIDGCN network itself (needs libtorch): the paper's size, shapes at any cloud size, the
// input layer's factorized sum against the plain edge MLP, radius graphs, the loss and its
// gradient, learning by overfitting one cloud, and weight files wrong in every way we could
// think of.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <set>

#include "geometry/error.h"
#include "learn/patch_cloud.h"
#include "learn/torch/bidgcn_net.h"

using namespace holefill;
using namespace holefill::learn;

namespace {

struct Cloud {
  torch::Tensor interior, boundary, boundaryUV, interiorUV;
};

Cloud cloud(int interior, uint64_t index) {
  PatchCloudOptions o;
  o.interior = interior;
  const PatchCloud c = randomPatchCloud(patchCloudSeed(PatchCloudSplit::Validation, index), o);
  const auto rows = [](const Eigen::MatrixXd& m) {
    torch::Tensor t = torch::empty({m.rows(), m.cols()});
    for (Eigen::Index i = 0; i < m.rows(); ++i)
      for (Eigen::Index j = 0; j < m.cols(); ++j) t[i][j] = m(i, j);
    return t;
  };
  return {rows(c.points.bottomRows(interior)), rows(c.points.topRows(34)), rows(c.uv.topRows(34)), rows(c.uv.bottomRows(interior))};
}

std::string tmp(const std::string& name) { return ::testing::TempDir() + "/" + name; }

std::string loadError(const std::string& path) {
  try {
    loadBidgcn(path);
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST(BidgcnNet, HasThePapersParameterCount) {
  torch::manual_seed(1);
  EXPECT_EQ(BidgcnNet()->parameterCount(), 192130);  // bidgcn.md sec. 4.1
}

TEST(BidgcnNet, AnswersEveryInteriorPointInsideTheSquareAtAnySize) {
  torch::manual_seed(1);
  BidgcnNet net;
  torch::NoGradGuard ng;
  for (int n : {200, 2000}) {
    const Cloud c = cloud(n, 0);
    const torch::Tensor uv = net->forward(c.interior, c.boundary, c.boundaryUV);
    ASSERT_EQ(uv.sizes(), torch::IntArrayRef({n, 2}));
    EXPECT_TRUE(torch::isfinite(uv).all().item<bool>());
    EXPECT_GT(uv.min().item<float>(), 0.0f);
    EXPECT_LT(uv.max().item<float>(), 1.0f);
    ASSERT_EQ(net->lastDegrees.size(), 6u);  // two input graphs, four feature graphs
    EXPECT_GE(net->lastDegrees[0], 1.0);     // every point is its own neighbour
  }
}

TEST(BidgcnNet, FactorizedInputLayerEqualsThePlainEdgeMlp) {
  torch::manual_seed(2);
  BidgcnNet net;
  torch::NoGradGuard ng;
  const Cloud c = cloud(300, 1);
  const torch::Tensor bx = torch::cat({c.boundary, c.boundaryUV}, -1);
  const RadiusGraph g = radiusGraph(c.interior, c.boundary, 0.3, 32);
  ASSERT_GT(g.src.size(0), 100);
  const torch::Tensor xi = c.interior.index_select(0, g.dst), xk = c.boundary.index_select(0, g.src);
  const torch::Tensor edges = torch::cat({xi, xk - xi, c.boundaryUV.index_select(0, g.src)}, -1);
  const torch::Tensor plain = torch::zeros({300, 64}).index_add(0, g.dst, net->boundaryEdges->forward(edges));
  const torch::Tensor fast = net->boundaryEdges->sumOverEdges(c.interior, bx, g);
  EXPECT_LT((plain - fast).abs().max().item<float>(), 1e-4 * plain.abs().max().item<float>());
}

TEST(BidgcnNet, RadiusGraphKeepsTheNearestWithinTheRadius) {
  // Points on a line at 0, 0.1, 0.2, ..., 0.9.
  const torch::Tensor x = torch::arange(10, torch::kFloat).mul(0.1).unsqueeze(1);
  const RadiusGraph g = radiusGraph(x, x, 0.25, 4);
  const auto d = g.degree.squeeze(1);
  EXPECT_EQ(d[0].item<float>(), 3);  // itself, 0.1, 0.2
  EXPECT_EQ(d[5].item<float>(), 4);  // five within 0.25, the nearest four kept
  std::set<int64_t> of5;
  for (int64_t e = 0; e < g.src.size(0); ++e) {
    const int64_t i = g.dst[e].item<int64_t>(), j = g.src[e].item<int64_t>();
    EXPECT_LE(std::abs(i - j), 2) << i << " " << j;  // within the radius
    if (i == 5) of5.insert(j);
  }
  // 3 and 7 are equally near 5: one of them is cut.
  EXPECT_EQ(of5.size(), 4u);
  for (int64_t j : {4, 5, 6}) EXPECT_EQ(of5.count(j), 1u) << j;
  const RadiusGraph none = radiusGraph(x, x + 5, 0.25, 4);  // nobody within reach
  EXPECT_EQ(none.src.size(0), 0);
  EXPECT_EQ(none.degree.sum().item<float>(), 0);
}

TEST(BidgcnNet, RadiusGraphEqualsBruteForceOnDenseFeatureClouds) {
  // 64-dimensional features as the dynamic layers see them: a row has hundreds of candidates
  // within the radius, of which the k nearest are kept; 300 rows span several row blocks.
  torch::manual_seed(5);
  const torch::Tensor f = torch::randn({300, 64}) * 0.012, t = torch::randn({200, 64}) * 0.012;
  const double r = 0.2;
  for (const int k : {8, 32, 1000}) {
    const RadiusGraph g = radiusGraph(f, t, r, k);
    const torch::Tensor d2 = (f.to(torch::kDouble).unsqueeze(1) - t.to(torch::kDouble).unsqueeze(0)).pow(2).sum(-1);
    int64_t e = 0, many = 0;
    for (int64_t i = 0; i < 300; ++i) {
      std::vector<std::pair<double, int64_t>> within;
      for (int64_t j = 0; j < 200; ++j)
        if (d2[i][j].item<double>() <= r * r) within.push_back({d2[i][j].item<double>(), j});
      std::sort(within.begin(), within.end());
      many += within.size() > 32;
      within.resize(std::min<size_t>(within.size(), k));
      std::vector<int64_t> want;
      for (const auto& w : within) want.push_back(w.second);
      std::sort(want.begin(), want.end());
      ASSERT_EQ(g.degree[i][0].item<float>(), float(want.size())) << "row " << i << " k " << k;
      for (int64_t j : want) {
        ASSERT_EQ(g.dst[e].item<int64_t>(), i);
        ASSERT_EQ(g.src[e++].item<int64_t>(), j) << "row " << i << " k " << k;
      }
    }
    EXPECT_EQ(e, g.src.size(0));
    EXPECT_GT(many, 100);  // the selection among many candidates is exercised
  }
}

TEST(BidgcnNet, LossVanishesAtExactParametersAndPullsTowardsThem) {
  const Cloud c = cloud(400, 2);
  const torch::Tensor exact = bezierFitLoss(c.interiorUV, c.interior, c.boundary, c.boundaryUV);
  EXPECT_LT(exact.item<double>(), 1e-12);  // float coordinates: not 0
  torch::Tensor uv = (c.interiorUV + 0.05 * torch::randn_like(c.interiorUV)).clamp(0, 1).requires_grad_(true);
  const torch::Tensor off = bezierFitLoss(uv, c.interior, c.boundary, c.boundaryUV);
  EXPECT_GT(off.item<double>(), 1e-5);
  off.backward();
  // A small step against the gradient lowers the loss.
  const torch::Tensor step = (uv - 1e-3 * uv.grad() / uv.grad().norm()).detach();
  EXPECT_LT(bezierFitLoss(step, c.interior, c.boundary, c.boundaryUV).item<double>(), off.item<double>());
}

TEST(BidgcnNet, OverfitsOneCloud) {
  torch::manual_seed(3);
  BidgcnNet net;
  const Cloud c = cloud(300, 3);
  torch::optim::Adam opt(net->parameters(), torch::optim::AdamOptions(2e-3));
  double first = 0, last = 0;
  for (int step = 0; step < 150; ++step) {
    const torch::Tensor loss = bezierFitLoss(net->forward(c.interior, c.boundary, c.boundaryUV), c.interior, c.boundary, c.boundaryUV);
    opt.zero_grad();
    loss.backward();
    opt.step();
    (step == 0 ? first : last) = loss.item<double>();
  }
  EXPECT_LT(last, first / 5) << first << " -> " << last;
}

TEST(BidgcnNet, WeightFilesRoundTripAndBadOnesAreRefused) {
  torch::manual_seed(4);
  BidgcnNet net;
  const std::string good = tmp("bidgcn_good.pt");
  saveBidgcn(net, good, "test");
  BidgcnNet back = loadBidgcn(good);
  const Cloud c = cloud(200, 4);
  torch::NoGradGuard ng;
  net->eval();
  EXPECT_EQ((net->forward(c.interior, c.boundary, c.boundaryUV) - back->forward(c.interior, c.boundary, c.boundaryUV)).abs().max().item<float>(), 0.0f);

  EXPECT_NE(loadError(tmp("no_such_bidgcn.pt")).find("not found"), std::string::npos);
  std::string bytes;
  {
    std::ifstream in(good, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  std::ofstream(tmp("bidgcn_cut.pt"), std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  EXPECT_NE(loadError(tmp("bidgcn_cut.pt")).find("truncated or corrupt"), std::string::npos);
  std::ofstream(tmp("bidgcn_text.pt")) << "not a network";
  EXPECT_NE(loadError(tmp("bidgcn_text.pt")).find("truncated or corrupt"), std::string::npos);
  {
    torch::serialize::OutputArchive a;  // a torch archive, but no HoleFill record
    a.write("something", torch::ones({2}));
    a.save_to(tmp("bidgcn_foreign.pt"));
  }
  EXPECT_NE(loadError(tmp("bidgcn_foreign.pt")).find("not a HoleFill BIDGCN file"), std::string::npos);
  {
    BidgcnNet bad;
    torch::NoGradGuard ng2;
    bad->hidden[0]->weight[0][0] = std::nanf("");
    saveBidgcn(bad, tmp("bidgcn_nan.pt"));
  }
  EXPECT_NE(loadError(tmp("bidgcn_nan.pt")).find("NaN"), std::string::npos);
}

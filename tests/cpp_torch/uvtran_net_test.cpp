// The network itself (needs libtorch): shapes, determinism, gradients through both stages by
// overfitting a few samples, and weight files that are wrong in every way we could think of.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

#include "geometry/error.h"
#include "learn/torch/uvtran_net.h"
#include "learn/uvtran_data.h"

using namespace holefill;
using namespace holefill::learn;

namespace {

UvtranConfig tiny() {
  UvtranConfig c;
  c.width = 32; c.heads = 2; c.layers = 1; c.feedForward = 64; c.dropout = 0.0;
  return c;
}

struct Few {
  torch::Tensor boundary, poles;
};

Few few(int n) {
  Few f{torch::empty({n, 128, 3}), torch::empty({n, 64, 3})};
  for (int s = 0; s < n; ++s) {
    const UvtranSample x = makeUvtranSample(uvtranSeed(UvtranSplit::Train, 1000 + s));
    for (int i = 0; i < 128; ++i)
      for (int c = 0; c < 3; ++c) f.boundary[s][i][c] = x.boundary[i](c);
    for (int i = 0; i < 64; ++i)
      for (int c = 0; c < 3; ++c) f.poles[s][i][c] = x.surface.poles(i, c);
  }
  return f;
}

std::string tmp(const std::string& name) { return ::testing::TempDir() + "/" + name; }

}  // namespace

TEST(UvtranNet, ShapesAndDeterminism) {
  torch::manual_seed(0);
  UvtranNet net(tiny());
  net->eval();
  torch::NoGradGuard ng;
  const Few f = few(3);
  const UvtranStage1 a = net->stage1(f.boundary);
  EXPECT_EQ(a.coarseLogits.sizes().vec(), (std::vector<int64_t>{3, 64, 3, 10}));
  EXPECT_EQ(a.knots.sizes().vec(), (std::vector<int64_t>{3, 4, 2}));
  EXPECT_EQ(a.features.sizes().vec(), (std::vector<int64_t>{3, 128, 32}));
  const torch::Tensor fine = net->stage2(a.features, decodeVoxels(a.coarseLogits));
  EXPECT_EQ(fine.sizes().vec(), (std::vector<int64_t>{3, 64, 3, 100}));
  const UvtranStage1 b = net->stage1(f.boundary);
  EXPECT_TRUE(torch::equal(a.coarseLogits, b.coarseLogits));
  EXPECT_TRUE(torch::equal(fine, net->stage2(b.features, decodeVoxels(b.coarseLogits))));
  // A batch of one gives what the same hole gives inside a batch.
  const UvtranStage1 one = net->stage1(f.boundary.slice(0, 1, 2));
  EXPECT_TRUE(torch::allclose(one.coarseLogits[0], a.coarseLogits[1], 1e-4, 1e-5));
  EXPECT_GT(net->parameterCount(), 10000);
  EXPECT_GT(net->flopsPerHole(), 1e6);
}

TEST(UvtranNet, DecodingAndTargetsRoundTrip) {
  const torch::Tensor p = torch::rand({2, 64, 3});
  for (int V : {10, 100}) {
    const torch::Tensor t = voxelTargets(p, V);
    torch::Tensor logits = torch::full({2, 64, 3, V}, -10.0);
    logits.scatter_(3, t.unsqueeze(-1), 10.0);
    const double err = (decodeVoxels(logits) - p).norm(2, -1).max().item<double>();
    EXPECT_LE(err, std::sqrt(3.0) / (2.0 * V) + 1e-6);
  }
}

TEST(UvtranNet, OverfitsAFewSamplesThroughBothStages) {
  torch::manual_seed(1);
  UvtranNet net(tiny());
  net->train();
  const Few f = few(4);
  const torch::Tensor tc = voxelTargets(f.poles, 10), tf = voxelTargets(f.poles, 100);
  torch::optim::Adam opt(net->parameters(), torch::optim::AdamOptions(3e-3));
  double ce1 = 0, ce2 = 0;
  for (int step = 0; step < 700; ++step) {
    const bool second = step >= 300;
    const UvtranStage1 s = net->stage1(f.boundary);
    torch::Tensor loss = voxelLoss(s.coarseLogits, tc, 0.0);
    ce1 = loss.item<double>();
    if (second) {
      const torch::Tensor l2 = voxelLoss(net->stage2(s.features, decodeVoxels(s.coarseLogits.detach())), tf, 0.0);
      ce2 = l2.item<double>();
      loss = loss + l2;
    }
    opt.zero_grad();
    loss.backward();
    if (step == 699) {  // both stages still receive gradient
      EXPECT_GT(net->fineHead->parameters()[0].grad().abs().sum().item<double>(), 0);
      EXPECT_GT(net->boundaryNet->parameters()[0].grad().abs().sum().item<double>(), 0);
    }
    opt.step();
  }
  EXPECT_LT(ce1, 0.05);
  EXPECT_LT(ce2, 0.3);  // from log(100) = 4.6
  net->eval();
  torch::NoGradGuard ng;
  const UvtranStage1 s = net->stage1(f.boundary);
  const torch::Tensor fine = decodeVoxels(net->stage2(s.features, decodeVoxels(s.coarseLogits)));
  EXPECT_LT((fine - f.poles).norm(2, -1).mean().item<double>(), 0.01);
}

TEST(UvtranWeights, RoundTripAndEveryKindOfBadFile) {
  torch::manual_seed(2);
  UvtranNet net(tiny());
  net->eval();
  const std::string good = tmp("uvtran_good.pt");
  saveUvtran(net, good, "test");
  UvtranNet back = loadUvtran(good);
  const Few f = few(1);
  torch::NoGradGuard ng;
  EXPECT_TRUE(torch::equal(net->stage1(f.boundary).coarseLogits, back->stage1(f.boundary).coarseLogits));

  auto message = [](const std::string& path) {
    try {
      loadUvtran(path);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message(tmp("missing.pt")).find("not found"), std::string::npos);
  std::string bytes;
  {
    std::ifstream in(good, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  std::ofstream(tmp("truncated.pt"), std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  EXPECT_NE(message(tmp("truncated.pt")).find("truncated or corrupt"), std::string::npos);
  std::ofstream(tmp("text.pt")) << "not weights at all\n";
  EXPECT_NE(message(tmp("text.pt")).find("truncated or corrupt"), std::string::npos);
  // A torch archive that is not ours.
  {
    torch::serialize::OutputArchive a;
    a.write("something", torch::ones({3}));
    a.save_to(tmp("foreign.pt"));
  }
  EXPECT_NE(message(tmp("foreign.pt")).find("not a HoleFill UVTran file"), std::string::npos);
  // Ours, but another format version.
  {
    torch::serialize::OutputArchive a;
    a.write("format", torch::tensor({int64_t(1)}));
    a.write("config", torch::tensor(tiny().toVector()));
    a.save_to(tmp("old.pt"));
  }
  EXPECT_NE(message(tmp("old.pt")).find("format"), std::string::npos);
  // The right format and config, parameters of another architecture.
  {
    UvtranConfig wide = tiny();
    wide.width = 48;
    UvtranNet other(wide);
    torch::serialize::OutputArchive a, params;
    a.write("format", torch::tensor({int64_t(20261122)}));
    a.write("config", torch::tensor(tiny().toVector()));
    other->save(params);
    a.write("net", params);
    a.save_to(tmp("mismatch.pt"));
  }
  EXPECT_NE(message(tmp("mismatch.pt")).find("wrong shape"), std::string::npos) << message(tmp("mismatch.pt"));
  // NaN parameters.
  {
    UvtranNet bad(tiny());
    bad->parameters()[0].data().fill_(std::nan(""));
    saveUvtran(bad, tmp("nan.pt"));
  }
  EXPECT_NE(message(tmp("nan.pt")).find("NaN"), std::string::npos);
}

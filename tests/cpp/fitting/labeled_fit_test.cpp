#include <gtest/gtest.h>

#include "fitting/labeled_fit.h"
#include "geometry/error.h"
#include "geometry/json_reader.h"
#include "mesh/mesh_holes.h"
#include "test_regions.h"

#include <random>

using namespace holefill;

TEST(JsonReader, ReadsValuesAndNamesWhereTheTextStopsBeingJson) {
  const JsonValue v = parseJson(R"( {"a": [1, -2.5e3, true, null], "b": {"c": "x\"y\n"}, "d": false} )");
  ASSERT_EQ(v.type, JsonValue::Type::Object);
  ASSERT_NE(v.find("a"), nullptr);
  EXPECT_EQ(v.find("a")->array.size(), 4u);
  EXPECT_EQ(v.find("a")->array[1].number, -2500);
  EXPECT_TRUE(v.find("a")->array[2].boolean);
  EXPECT_EQ(v.find("a")->array[3].type, JsonValue::Type::Null);
  EXPECT_EQ(v.find("b")->find("c")->string, "x\"y\n");
  EXPECT_EQ(v.find("zz"), nullptr);
  for (const char* bad : {"", "{", "[1,]", "{\"a\" 1}", "\"open", "1 2", "tru", "[1e999]", "{\"a\":\x01}"}) {
    try {
      parseJson(bad, "t.json");
      ADD_FAILURE() << "accepted: " << bad;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("'t.json' is not valid JSON"), std::string::npos) << e.what();
    }
  }
}

TEST(LabeledFit, ParsesLabelsAndRunsEndToEndOnAFlatRectangle) {
  const auto labels = parseLabelsJson(R"({"segments": [{"label": "S", "vertices": [0, 1, 2]}, {"label": "North", "vertices": [8, 7, 6]}]})");
  ASSERT_EQ(labels.size(), 2u);
  EXPECT_EQ(labels[0].side, Side::South);
  EXPECT_EQ(labels[1].side, Side::North);
  EXPECT_EQ(labels[1].vertices, (std::vector<int>{8, 7, 6}));
  EXPECT_THROW(parseLabelsJson(R"({"segments": [{"label": "S", "vertices": [0, 1.5]}]})"), Error);
  EXPECT_THROW(parseLabelsJson(R"({"segments": [{"vertices": [0, 1]}]})"), Error);
  EXPECT_THROW(parseLabelsJson(R"([1, 2])"), Error);

  // A flat 3×3-vertex square labeled S and N: parameterized, extended, fitted, trimmed.
  TriangleMesh m;
  m.vertices.resize(9, 3);
  for (int v = 0; v < 9; ++v) m.vertices.row(v) << v % 3, v / 3, 0;
  m.triangles.resize(8, 3);
  m.triangles << 0, 1, 4, 0, 4, 3, 1, 2, 5, 1, 5, 4, 3, 4, 7, 3, 7, 6, 4, 5, 8, 4, 8, 7;
  LabeledFitOptions o;
  o.fit.controlU = o.fit.controlV = 4;
  const LabeledFitResult r = fitLabeled(m, labels, o);
  EXPECT_NEAR(r.parameterization.width, 2, 1e-6);
  EXPECT_NEAR(r.parameterization.height, 2, 1e-6);
  EXPECT_LT(r.fit.dataMax, 1e-9);  // a plane is fitted exactly
  EXPECT_TRUE(r.fit.valid);
  EXPECT_NE(r.toJson().find("\"weak_control_points\""), std::string::npos);
}

// Issue 21, never a crash: random small regions (unions of random disks over a grid, lifted onto a
// random quadric, in either orientation) with their boundary split into four labeled runs at random
// corners. Each must give a face or a holefill::Error, never a crash and never another exception.
TEST(LabeledFit, RandomRegionsAndLabelSplitsGiveAFaceOrAClearError) {
  std::mt19937 rng(20261203);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int faces = 0, errors = 0;
  for (int round = 0; round < 40; ++round) {
    SCOPED_TRACE("round " + std::to_string(round));
    const int disks = 1 + static_cast<int>(unit(rng) * 3);
    std::vector<Eigen::Vector3d> d;  // centre x, y and radius, in [0, 1]
    for (int k = 0; k < disks; ++k) d.emplace_back(0.25 + 0.5 * unit(rng), 0.25 + 0.5 * unit(rng), 0.15 + 0.2 * unit(rng));
    const double a = unit(rng) - 0.5, b = unit(rng) - 0.5, c = unit(rng) - 0.5;
    Eigen::MatrixX2d uv;
    TriangleMesh region = testregions::gridRegion(
        16, 16, 1.0 / 16,
        [&](double x, double y) {
          for (const auto& q : d)
            if (std::hypot(x - q.x(), y - q.y()) < q.z()) return true;
          return false;
        },
        [&](double x, double y) { return Eigen::Vector3d(x, y, a * x * x + b * x * y + c * y * y); }, uv);
    if (region.triangles.rows() < 2) continue;
    if (round % 2) region.triangles.col(1).swap(region.triangles.col(2));
    try {
      const MeshHoleReport holes = findMeshHoles(region);
      if (holes.holes.empty()) continue;
      const std::vector<int>& loop = holes.holes[0].loop;
      const int n = static_cast<int>(loop.size());
      std::vector<int> cut;
      for (int k = 0; k < 4; ++k) cut.push_back(static_cast<int>(unit(rng) * n));
      std::sort(cut.begin(), cut.end());
      std::vector<LabeledSegment> labels;
      for (int k = 0; k < 4; ++k) {
        LabeledSegment seg{static_cast<Side>(k), {}};
        for (int i = cut[k];; i = (i + 1) % n) {
          seg.vertices.push_back(loop[i]);
          if (i == cut[(k + 1) % 4]) break;
        }
        labels.push_back(seg);
      }
      LabeledFitOptions o;
      o.fit.controlU = o.fit.controlV = 8;
      const LabeledFitResult r = fitLabeled(region, labels, o);
      EXPECT_TRUE(r.fit.surface.poles.allFinite());
      ++faces;
    } catch (const Error&) {
      ++errors;  // a clear refusal is an answer
    }
  }
  std::printf("random regions: %d faces, %d clear errors\n", faces, errors);
  EXPECT_GT(faces, 0);
}

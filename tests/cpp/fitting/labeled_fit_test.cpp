#include <gtest/gtest.h>

#include "fitting/labeled_fit.h"
#include "geometry/error.h"
#include "geometry/json_reader.h"

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

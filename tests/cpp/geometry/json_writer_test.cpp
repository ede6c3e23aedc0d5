#include "geometry/json_writer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "geometry/json_reader.h"

using namespace holefill;

TEST(JsonWriter, WritesWhatTheReaderReadsBack) {
  JsonWriter j;
  j.beginObject();
  j.field("name", std::string("Edge \"7\"\\\n\t"));
  j.field("g1", 1.25e-4).field("n", 42).field("ok", true);
  j.field("edges", std::vector<int>{3, 5, 8});
  j.field("labels", std::vector<std::string>{"N", "S"});
  j.key("nested").raw("{\"x\": [1]}");
  j.key("empty").beginArray().endArray();
  j.endObject();
  const JsonValue v = parseJson(j.str(), "report");
  EXPECT_EQ(v.find("name")->string, "Edge \"7\"\\\n\t");
  EXPECT_DOUBLE_EQ(v.find("g1")->number, 1.25e-4);
  EXPECT_DOUBLE_EQ(v.find("n")->number, 42);
  EXPECT_TRUE(v.find("ok")->boolean);
  ASSERT_EQ(v.find("edges")->array.size(), 3u);
  EXPECT_DOUBLE_EQ(v.find("edges")->array[2].number, 8);
  EXPECT_EQ(v.find("labels")->array[1].string, "S");
  EXPECT_DOUBLE_EQ(v.find("nested")->find("x")->array[0].number, 1);
  EXPECT_TRUE(v.find("empty")->array.empty());
}

TEST(JsonWriter, NonFiniteNumbersAreNullSoThePythonDoorCanParseThem) {
  JsonWriter j;
  j.beginArray().value(std::numeric_limits<double>::infinity()).value(std::nan("")).value(-0.5).endArray();
  const JsonValue v = parseJson(j.str());
  ASSERT_EQ(v.array.size(), 3u);
  EXPECT_EQ(v.array[0].type, JsonValue::Type::Null);
  EXPECT_EQ(v.array[1].type, JsonValue::Type::Null);
  EXPECT_DOUBLE_EQ(v.array[2].number, -0.5);
}

TEST(JsonWriter, DoublesSurviveTheRoundTripToTheLastBit) {
  const double x = 0.1 + 0.2, y = 1.0 / 3.0 * 1e-300;
  JsonWriter j;
  j.beginArray().value(x).value(y).endArray();
  const JsonValue v = parseJson(j.str());
  EXPECT_EQ(v.array[0].number, x);
  EXPECT_EQ(v.array[1].number, y);
}

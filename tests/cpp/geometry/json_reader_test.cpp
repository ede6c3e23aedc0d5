#include "geometry/json_reader.h"

#include <gtest/gtest.h>

#include "geometry/error.h"

using namespace holefill;

TEST(JsonReader, KeepsUnicodeEscapesAsWrittenAndFindsOnlyInObjects) {
  const JsonValue v = parseJson(R"( {"a": [1, -2.5e3, true, false, null], "s": "x\"y\\n\u00e9", "o": {"k": {}}} )");
  ASSERT_EQ(v.type, JsonValue::Type::Object);
  const JsonValue* a = v.find("a");
  ASSERT_NE(a, nullptr);
  ASSERT_EQ(a->array.size(), 5u);
  EXPECT_DOUBLE_EQ(a->array[0].number, 1.0);
  EXPECT_DOUBLE_EQ(a->array[1].number, -2500.0);
  EXPECT_TRUE(a->array[2].boolean);
  EXPECT_EQ(a->array[3].type, JsonValue::Type::Bool);
  EXPECT_FALSE(a->array[3].boolean);
  EXPECT_EQ(a->array[4].type, JsonValue::Type::Null);
  EXPECT_EQ(v.find("s")->string, "x\"y\\n\\u00e9");  // \" and \\ decoded, \uXXXX kept as written
  EXPECT_EQ(v.find("o")->find("k")->type, JsonValue::Type::Object);
  EXPECT_EQ(v.find("missing"), nullptr);
  EXPECT_EQ(a->find("a"), nullptr);  // not an object
}

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

TEST(JsonReader, DeepNestingIsRefusedNotACrash) {
  // A truncated or hostile file of brackets must give an error, not exhaust the stack.
  const std::string deep(200000, '[');
  EXPECT_THROW(parseJson(deep, "deep.json"), Error);
}

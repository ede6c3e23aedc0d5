#include <gtest/gtest.h>

#include "expect_error.h"
#include "geometry/error.h"
#include "geometry/json_reader.h"
#include "options/option_schema.h"

using namespace holefill;

namespace {

struct Toy {
  double gap = 0.25;
  int count = 7;
  bool on = true;
  std::string file;
};

OptionSchema<Toy> toySchema() {
  OptionField gap{"gap", "--gap", OptionKind::Number, "model units", "how far"};
  gap.minimum = 0;
  gap.minimumExcluded = true;
  OptionField count{"count", "--count", OptionKind::Integer, "", "how many"};
  count.minimum = 2;
  count.maximum = 9;
  OptionField on{"on", "--off", OptionKind::Bool, "", "whether"};
  on.flagSets = false;
  return {numberOption<Toy>(gap, [](Toy& t) -> double& { return t.gap; }),
          integerOption<Toy>(count, [](Toy& t) -> int& { return t.count; }),
          boolOption<Toy>(on, [](Toy& t) -> bool& { return t.on; }),
          textOption<Toy>(OptionField{"file", "", OptionKind::Text, "", "which"}, [](Toy& t) -> std::string& { return t.file; })};
}

std::string refusal(const OptionSchema<Toy>& s, const std::string& name, const std::string& text) {
  Toy t;
  try {
    setOption(s, t, name, text);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

}  // namespace

// The schema's JSON carries every field once, with the struct's own defaults typed.
TEST(OptionSchema, ListsEveryFieldWithTheStructsDefaults) {
  const JsonValue j = parseJson(optionSchemaJson(toySchema()));
  ASSERT_EQ(j.array.size(), 4u);
  EXPECT_EQ(j.array[0].find("name")->string, "gap");
  EXPECT_EQ(j.array[0].find("default")->number, 0.25);
  EXPECT_EQ(j.array[0].find("unit")->string, "model units");
  EXPECT_TRUE(j.array[0].find("minimum_excluded")->boolean);
  EXPECT_EQ(j.array[0].find("maximum")->type, JsonValue::Type::Null);  // open
  EXPECT_EQ(j.array[1].find("default")->number, 7);
  EXPECT_EQ(j.array[1].find("maximum")->number, 9);
  EXPECT_TRUE(j.array[2].find("default")->boolean);
  EXPECT_FALSE(j.array[2].find("flag_sets")->boolean);
  EXPECT_EQ(j.array[3].find("default")->string, "");
}

TEST(OptionSchema, SetsFromTextAndReadsBack) {
  const OptionSchema<Toy> s = toySchema();
  Toy t;
  setOption(s, t, "gap", "1e-3");
  setOption(s, t, "count", "9");
  setOption(s, t, "on", "false");
  setOption(s, t, "file", "/tmp/w.pt");
  EXPECT_EQ(t.gap, 1e-3);
  EXPECT_EQ(t.count, 9);
  EXPECT_FALSE(t.on);
  EXPECT_EQ(t.file, "/tmp/w.pt");
  EXPECT_EQ(s[0].get(t), "0.001");  // the shortest text that reads back
  EXPECT_EQ(s[1].get(t), "9");
  EXPECT_EQ(s[2].get(t), "false");
  for (double v : {0.1, 1.0 / 3, 2500.0, 1e-300, -7.25e22}) EXPECT_EQ(std::stod(formatOptionNumber(v)), v) << v;
}

TEST(OptionSchema, RefusesOutOfRangeAndMalformedValuesNamingTheField) {
  const OptionSchema<Toy> s = toySchema();
  EXPECT_NE(refusal(s, "gap", "0").find("gap must be positive, got '0'"), std::string::npos);
  EXPECT_NE(refusal(s, "gap", "1x").find("gap must be a number"), std::string::npos);
  EXPECT_NE(refusal(s, "gap", "nan").find("gap must be positive"), std::string::npos);
  EXPECT_NE(refusal(s, "gap", "").find("gap must be a number"), std::string::npos);
  EXPECT_NE(refusal(s, "count", "2.5").find("count must be a whole number"), std::string::npos);
  EXPECT_NE(refusal(s, "count", "10").find("count must be a whole number between 2 and 9"), std::string::npos);
  EXPECT_NE(refusal(s, "on", "yes").find("on must be true or false"), std::string::npos);
  EXPECT_NE(refusal(s, "gpa", "1").find("unknown option 'gpa': the options are gap, count, on, file"), std::string::npos);
}

TEST(OptionSchema, AChoiceIsOneOfItsValues) {
  OptionField f{"mode", "--mode", OptionKind::Choice, "", "which way", {"a", "b"}};
  EXPECT_EQ(checkOptionChoice(f, "b"), "b");
  expectErrorNaming([&] { checkOptionChoice(f, "c"); }, "mode must be one of a, b, got 'c'");
}

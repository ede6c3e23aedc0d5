#include <gtest/gtest.h>

#include "geometry/error.h"
#include "geometry/json_reader.h"
#include "options/option_sets.h"

using namespace holefill;

TEST(OptionSets, EverySetNamedHasASchemaAndAnUnknownSetIsRefused) {
  for (const auto& name : optionSetNames()) {
    const JsonValue j = parseJson(optionSetJson(name));
    EXPECT_GT(j.array.size(), 0u) << name;
  }
  try {
    optionSetJson("nope");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("the sets are fill"), std::string::npos) << e.what();
  }
}

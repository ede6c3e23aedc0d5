#include <gtest/gtest.h>

#include "expect_error.h"
#include "geometry/error.h"
#include "geometry/json_reader.h"
#include "options/option_sets.h"

using namespace holefill;

TEST(OptionSets, EverySetNamedHasASchemaAndAnUnknownSetIsRefused) {
  for (const auto& name : optionSetNames()) {
    const JsonValue j = parseJson(optionSetJson(name));
    EXPECT_GT(j.array.size(), 0u) << name;
  }
  expectErrorNaming([] { optionSetJson("nope"); }, "the sets are fill, labeled_fit, mesh_fill, gnurbs, point_fit");
}

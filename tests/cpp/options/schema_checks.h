// What every option schema must hold, checked alike for each set: unique names and flags, a doc
// for every field, and a default that the field itself accepts back.
#pragma once

#include <gtest/gtest.h>

#include <set>

#include "options/option_schema.h"

template <class O>
void expectWellFormedSchema(const holefill::OptionSchema<O>& s) {
  const O defaults{};
  std::set<std::string> names, flags;
  for (const auto& b : s) {
    EXPECT_TRUE(names.insert(b.field.name).second) << b.field.name;
    if (!b.field.flag.empty()) EXPECT_TRUE(flags.insert(b.field.flag).second) << b.field.flag;
    EXPECT_FALSE(b.field.doc.empty()) << b.field.name;
    O copy;
    EXPECT_NO_THROW(b.set(copy, b.get(defaults))) << b.field.name;
  }
}

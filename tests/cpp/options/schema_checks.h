// What every option schema must hold, checked alike for each set: unique names and flags, a doc
// for every field, and a default that the field itself accepts back.
#pragma once

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <utility>
#include <vector>

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

// Sets one value for every field of `s`, in the schema's order (a field without one fails).
using OptionValues = std::vector<std::pair<std::string, std::string>>;

template <class O>
void setEveryOption(const holefill::OptionSchema<O>& s, O& o, const OptionValues& values) {
  ASSERT_EQ(values.size(), s.size()) << "a field without a case here";
  for (const auto& [name, text] : values) holefill::setOption(s, o, name, text);
}

// ... and that each field reads back the text it was set from.
template <class O>
void expectEveryOptionReadsBack(const holefill::OptionSchema<O>& s, const O& o, const OptionValues& values) {
  for (size_t k = 0; k < s.size() && k < values.size(); ++k) EXPECT_EQ(s[k].get(o), values[k].second) << s[k].field.name;
}

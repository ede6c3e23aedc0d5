// A refusal as the tests expect it: holefill::Error thrown, its message naming what was wrong.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "geometry/error.h"

template <class F>
void expectErrorNaming(F&& f, const std::string& word) {
  try {
    f();
    ADD_FAILURE() << "accepted; expected an error naming '" << word << "'";
  } catch (const holefill::Error& e) {
    EXPECT_NE(std::string(e.what()).find(word), std::string::npos) << e.what();
  }
}

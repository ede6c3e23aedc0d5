#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>

#include "geometry/error.h"
#include "learn/learn_library.h"

using namespace holefill;

// The learned models' library loads once, with every entry point, and names the libtorch it
// runs on; the shipped weights are found next to it and are torch archives (zip files).
TEST(LearnLibrary, LoadsOnceWithEveryEntryAndFindsTheShippedWeights) {
  const learn::LearnLibrary& a = learn::learnLibrary();
  const learn::LearnLibrary& b = learn::learnLibrary();
  EXPECT_EQ(&a, &b);
  ASSERT_NE(a.predict, nullptr);
  ASSERT_NE(a.bidgcnPredict, nullptr);
  ASSERT_NE(a.main, nullptr);
  ASSERT_NE(a.info, nullptr);
  EXPECT_NE(std::string(a.info()).find("libtorch"), std::string::npos) << a.info();
  for (const std::string& w : {learn::defaultUvtranWeights(), learn::defaultBidgcnWeights()}) {
    ASSERT_FALSE(w.empty());
    std::ifstream in(w, std::ios::binary);
    char magic[2] = {0, 0};
    in.read(magic, 2);
    EXPECT_TRUE(magic[0] == 'P' && magic[1] == 'K') << w << " is not a zip (torch) archive";
  }
}

// A weights path given in the environment wins over the shipped one.
TEST(LearnLibrary, TheEnvironmentNamesOtherWeights) {
  const char* before = std::getenv("HOLEFILL_UVTRAN_WEIGHTS");
  const std::string kept = before ? before : "";
  setenv("HOLEFILL_UVTRAN_WEIGHTS", "/tmp/elsewhere.pt", 1);
  EXPECT_EQ(learn::defaultUvtranWeights(), "/tmp/elsewhere.pt");
  if (before) setenv("HOLEFILL_UVTRAN_WEIGHTS", kept.c_str(), 1);
  else unsetenv("HOLEFILL_UVTRAN_WEIGHTS");
  EXPECT_NE(learn::defaultUvtranWeights(), "/tmp/elsewhere.pt");
}

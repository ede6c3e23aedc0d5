#include "geometry/text_file.h"

#include <gtest/gtest.h>

#include "geometry/error.h"

namespace holefill {
namespace {

TEST(TextFile, NumbersAreWholeTokens) {
  double x = 0;
  long long n = 0;
  EXPECT_TRUE(parseDouble("-1.5e-3", x));
  EXPECT_EQ(x, -1.5e-3);
  EXPECT_FALSE(parseDouble("1.5x", x));
  EXPECT_FALSE(parseDouble("", x));
  EXPECT_TRUE(parseInt("-42", n));
  EXPECT_EQ(n, -42);
  EXPECT_FALSE(parseInt("42.0", n));
  EXPECT_TRUE(parseInt("9223372036854775807", n));
  EXPECT_EQ(n, 9223372036854775807LL);
}

// Found by fuzzing: strtoll clamps an out-of-range count to 2^63 − 1, which then overflowed the
// OFF reader's size check. Out of range is not a number.
TEST(TextFile, OutOfRangeIntegersAreRefused) {
  long long n = 0;
  EXPECT_FALSE(parseInt("9223372036854775808", n));
  EXPECT_FALSE(parseInt("4888888888888888888888888888888888", n));
  EXPECT_FALSE(parseInt("-9223372036854775809", n));
}

TEST(TextFile, ExtensionsAreLowerCase) {
  EXPECT_EQ(fileExtension("/a.b/Part.STEP"), "step");
  EXPECT_EQ(fileExtension("/a.b/part"), "");
  EXPECT_THROW(readFileBytes("/nonexistent/file"), Error);
}

}  // namespace
}  // namespace holefill

#include "geometry/error.h"

#include <gtest/gtest.h>

#include <Standard_DomainError.hxx>
#include <Standard_Failure.hxx>

using namespace holefill;

TEST(Error, CheckFailuresNameTheConditionAndPlace) {
  try {
    HF_CHECK(1 + 1 == 3, "arithmetic is broken");
    FAIL() << "HF_CHECK did not throw";
  } catch (const Error& e) {
    const std::string w = e.what();
    EXPECT_NE(w.find("arithmetic is broken"), std::string::npos);
    EXPECT_NE(w.find("error_test.cpp"), std::string::npos);
    EXPECT_NE(w.find("1 + 1 == 3"), std::string::npos);
  }
}

TEST(Error, OcctFailuresAlwaysSaySomething) {
  EXPECT_EQ(occtFailure(Standard_DomainError("the curve is degenerate")), "OpenCASCADE failed: the curve is degenerate");
  // OCCT often raises with no message: the exception's type is then what the user reads.
  EXPECT_EQ(occtFailure(Standard_DomainError("")), "OpenCASCADE failed: Standard_DomainError (no message)");
  EXPECT_EQ(occtFailure(Standard_Failure()), "OpenCASCADE failed: Standard_Failure (no message)");
}

#include "geometry/plugin_library.h"

#include <gtest/gtest.h>

#include <dlfcn.h>

using namespace holefill;

TEST(PluginLibrary, SaysWhereItLookedWhenMissing) {
  std::string path, tried;
  EXPECT_EQ(openPluginLibrary("libholefill_no_such_plugin.so", nullptr, "/nonexistent/libx.so", path, tried), nullptr);
  EXPECT_NE(tried.find("libholefill_no_such_plugin.so (missing)"), std::string::npos) << tried;
  EXPECT_NE(tried.find("/nonexistent/libx.so (missing)"), std::string::npos) << tried;
  EXPECT_TRUE(path.empty());
}

// The STEP library of this build opens from the build path given (as the core finds it in tests).
TEST(PluginLibrary, OpensAnExistingLibraryAndReportsItsPath) {
  std::string path, tried;
  void* h = openPluginLibrary("libholefill_step_not_here.so", nullptr, HOLEFILL_TEST_STEP_LIBRARY, path, tried);
  ASSERT_NE(h, nullptr) << tried;
  EXPECT_EQ(path, HOLEFILL_TEST_STEP_LIBRARY);
  EXPECT_NE(dlsym(h, "holefill_step_read"), nullptr);
}

#include <gtest/gtest.h>

#include <BRepGProp.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <GProp_GProps.hxx>
#include <dlfcn.h>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>

#include "geometry/plugin_library.h"

// libholefill_step.so's two plain entry points, called as step_io calls them: a box written and
// read back keeps its volume; a file that is not STEP comes back non-zero with a message, cut to
// the buffer it was given and terminated.
namespace {

using ReadFn = int (*)(const char*, TopoDS_Shape*, char*, int);
using WriteFn = int (*)(const TopoDS_Shape*, const char*, char*, int);

double volume(const TopoDS_Shape& s) {
  GProp_GProps g;
  BRepGProp::VolumeProperties(s, g);
  return g.Mass();
}

}  // namespace

TEST(StepLibrary, ItsEntryPointsWriteAndReadAShapeAndReportFailuresInTheBuffer) {
  std::string path, tried;
  void* h = holefill::openPluginLibrary("libholefill_step.so", "HOLEFILL_STEP_LIBRARY", HOLEFILL_TEST_STEP_LIBRARY, path, tried);
  ASSERT_NE(h, nullptr) << tried;
  const auto read = reinterpret_cast<ReadFn>(dlsym(h, "holefill_step_read"));
  const auto write = reinterpret_cast<WriteFn>(dlsym(h, "holefill_step_write"));
  ASSERT_NE(read, nullptr);
  ASSERT_NE(write, nullptr);
  const std::string file = testing::TempDir() + "step_library_box.step";
  const TopoDS_Shape box = BRepPrimAPI_MakeBox(3, 4, 5).Shape();
  char err[256] = "";
  ASSERT_EQ(write(&box, file.c_str(), err, sizeof err), 0) << err;
  TopoDS_Shape back;
  ASSERT_EQ(read(file.c_str(), &back, err, sizeof err), 0) << err;
  EXPECT_NEAR(volume(back), 60.0, 1e-6);
  std::ofstream(file) << "this is not STEP\n";
  char small[12];
  std::memset(small, 'x', sizeof small);
  EXPECT_NE(read(file.c_str(), &back, small, sizeof small), 0);
  EXPECT_NE(std::memchr(small, '\0', sizeof small), nullptr) << "the message overran its buffer";
  std::remove(file.c_str());
}

#include "brep/step_io.h"

#include <gtest/gtest.h>

#include <BRepGProp.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <GProp_GProps.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "brep/shape_io.h"
#include "geometry/error.h"

using namespace holefill;

namespace {
std::string scratch(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("holefill_step_io_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  return (dir / name).string();
}
double volume(const TopoDS_Shape& s) {
  GProp_GProps p;
  BRepGProp::VolumeProperties(s, p);
  return p.Mass();
}
}  // namespace

// STEP goes through libholefill_step.so, loaded on first use: a box survives the round trip.
TEST(StepIo, BoxRoundTripsThroughTheStepLibrary) {
  const TopoDS_Shape box = BRepPrimAPI_MakeBox(10, 20, 30).Shape();
  const std::string path = scratch("box.step");
  writeShape(box, path);  // the public door: atomically, through writeStep
  const TopoDS_Shape back = readShape(path);
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(back, TopAbs_FACE, faces);
  EXPECT_EQ(faces.Extent(), 6);
  EXPECT_NEAR(volume(back), 6000.0, 1e-6);
  EXPECT_NEAR(volume(readStep(path)), 6000.0, 1e-6);
  std::filesystem::remove_all(std::filesystem::path(path).parent_path());
}

TEST(StepIo, GarbageIsRefusedWithTheFileNamed) {
  const std::string path = scratch("garbage.step");
  std::ofstream(path) << "ISO-10303-21;\nthis is not step\n";
  try {
    readStep(path);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("garbage.step"), std::string::npos) << e.what();
  }
  std::filesystem::remove_all(std::filesystem::path(path).parent_path());
}

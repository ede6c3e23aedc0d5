#include "brep/shape_io.h"

#include <gtest/gtest.h>

#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS_Shape.hxx>
#include <chrono>

#include "brep/sample_models.h"
#include "geometry/error.h"

namespace holefill {
namespace {

std::string errorOf(const std::string& text, double timeLimit = 60.0) {
  try {
    shapeFromBrepString(text, timeLimit);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(ShapeIo, BrepTextRoundTrips) {
  const TopoDS_Shape box = samples::boxMinusFace();
  const TopoDS_Shape back = shapeFromBrepString(shapeToBrepString(box));
  ASSERT_FALSE(back.IsNull());
  for (const TopAbs_ShapeEnum kind : {TopAbs_VERTEX, TopAbs_EDGE, TopAbs_FACE}) {
    TopTools_IndexedMapOfShape a, b;  // (the text differs in OCCT's "checked" flags only)
    TopExp::MapShapes(box, kind, a);
    TopExp::MapShapes(back, kind, b);
    EXPECT_EQ(a.Extent(), b.Extent());
  }
}

// Cut-off text, NUL bytes and inflated counts are refused before OCCT reads them (issue 22).
TEST(ShapeIo, DamagedBrepTextIsRefused) {
  const std::string box = shapeToBrepString(samples::boxMinusFace());
  EXPECT_NE(errorOf(box.substr(0, box.size() / 2)).find("cut off"), std::string::npos);
  EXPECT_NE(errorOf(box.substr(0, 200) + std::string(3, '\0') + box.substr(200)).find("NUL"), std::string::npos);
  EXPECT_NE(errorOf("").find("empty"), std::string::npos);
}

// Found by fuzzing (tests/fuzz/corpus/brep_text/edge_representation_hang): a token OCCT fails to
// read inside an edge's list of representations sends its reader round for ever. The Python
// door reads BREP text in FreeCAD's own process, so the text is first read in a throwaway child
// that is stopped at the time limit.
TEST(ShapeIo, BrepTextTheReaderHangsOnIsRefusedInTime) {
  std::string text = shapeToBrepString(samples::boxMinusFace());
  const size_t at = text.rfind("\n2  ");  // the last edge's last pcurve: "2  curve surface location range"
  ASSERT_NE(at, std::string::npos);
  text.replace(at + 1, text.find('\n', at + 1) - at - 1, "2  24Triangulations101000");
  const auto start = std::chrono::steady_clock::now();
  const std::string message = errorOf(text, 2.0);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_NE(message.find("took longer than 2 s"), std::string::npos) << message;
  EXPECT_LT(seconds, 10.0);
}

// Found by fuzzing: OCCT's reader dereferences a null basis curve when a 2D curve's record says
// "offset" (9) and the basis does not follow. The crash stays in the throwaway child, which dies of
// its signal (FreeCAD's own handlers, inherited, once turned it into a read error, and the caller
// then crashed FreeCAD re-reading the text in its own process).
TEST(ShapeIo, BrepTextTheReaderCrashesOnIsRefused) {
  std::string text = shapeToBrepString(samples::boxMinusFace());
  const size_t at = text.find("Curve2ds ");
  ASSERT_NE(at, std::string::npos);
  const size_t first = text.find('\n', at) + 1;  // the first 2D curve's record: "1 ..." (a line)
  ASSERT_EQ(text[first], '1');
  text[first] = '9';
  EXPECT_NE(errorOf(text).find("the reader crashed on it"), std::string::npos) << errorOf(text);
}

}  // namespace
}  // namespace holefill

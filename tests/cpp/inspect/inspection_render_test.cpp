#include "inspect/inspection_render.h"

#include <BRepPrimAPI_MakeSphere.hxx>
#include <gtest/gtest.h>

#include "brep/sample_models.h"
#include "geometry/error.h"
#include "png_decode.h"

using namespace holefill;

namespace {

struct Stats {
  double covered = 0, dark = 0, light = 0, reddish = 0, bluish = 0;
};
Stats stats(const RasterImage& im) {
  Stats s;
  const double n = static_cast<double>(im.width) * im.height;
  for (int y = 0; y < im.height; ++y)
    for (int x = 0; x < im.width; ++x) {
      const std::uint8_t* p = im.at(x, y);
      const bool white = p[0] == 255 && p[1] == 255 && p[2] == 255;
      s.covered += !white / n;
      s.dark += (p[0] + p[1] + p[2] < 120) / n;
      s.light += (!white && p[0] + p[1] + p[2] > 600) / n;
      s.reddish += (p[0] > p[2] + 60) / n;
      s.bluish += (p[2] > p[0] + 60) / n;
    }
  return s;
}

}  // namespace

TEST(InspectionRender, ZebraSphereShowsBothStripeColoursAndThePngRoundTrips) {
  RenderOptions o;
  o.width = 320;
  o.height = 240;
  o.legend = false;
  const RenderResult r = renderInspection(BRepPrimAPI_MakeSphere(2.0).Shape(), o);
  const Stats s = stats(r.image);
  EXPECT_NEAR(s.covered, M_PI * std::pow(0.92 * 240 / 2, 2) / (320 * 240), 0.03);  // the sphere's disc
  EXPECT_GT(s.dark, 0.1);
  EXPECT_GT(s.light, 0.1);
  const RasterImage back = testpng::decode(encodePng(r.image));
  EXPECT_EQ(back.rgb, r.image.rgb);
}

TEST(InspectionRender, CurvatureMapOfASaddleFillIsDivergingWithALegend) {
  RenderOptions o = parseRenderOptions({{"mode", "curvature"}, {"quantity", "gauss"}, {"size", "400x300"}});
  const RenderResult r = renderInspection(samples::byName("cc_valence5"), o);
  EXPECT_TRUE(r.scale.diverging);
  EXPECT_DOUBLE_EQ(r.scale.low, -r.scale.high);
  EXPECT_LT(r.valueMin, 0.0);
  const Stats s = stats(r.image);
  EXPECT_GT(s.bluish, 0.02);  // mostly negative Gaussian curvature: blue, and the legend's red end
  EXPECT_GT(s.reddish, 0.002);
  EXPECT_GT(s.covered, 0.1);
  EXPECT_NE(toJson(r, o).find("\"quantity\":\"gauss\""), std::string::npos);
}

TEST(InspectionRender, RejectsBadOptions) {
  EXPECT_THROW(parseRenderOptions({{"mode", "xray"}}), Error);
  EXPECT_THROW(parseRenderOptions({{"size", "big"}}), Error);
  EXPECT_THROW(parseRenderOptions({{"view", "1,2"}}), Error);
  EXPECT_THROW(parseRenderOptions({{"scale-range", "1,nan"}}), Error);
  EXPECT_THROW(parseRenderOptions({{"colour", "red"}}), Error);
  RenderOptions o;
  o.stripes.width = 1.5;
  EXPECT_THROW(renderInspection(BRepPrimAPI_MakeSphere(1.0).Shape(), o), Error);
  o = RenderOptions();
  o.width = 5;
  EXPECT_THROW(renderInspection(BRepPrimAPI_MakeSphere(1.0).Shape(), o), Error);
  EXPECT_EQ(viewFromString("top").view.z(), -1.0);
  EXPECT_NEAR(viewFromString("0,0,2").view.z(), 1.0, 1e-15);
}

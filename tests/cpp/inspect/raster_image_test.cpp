#include "inspect/raster_image.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

#include "geometry/error.h"
#include "png_decode.h"

using namespace holefill;

TEST(RasterImage, PixelsOutsideAreIgnoredAndRectanglesAreClipped) {
  RasterImage im(5, 4, {10, 20, 30});
  ASSERT_EQ(im.rgb.size(), 5u * 4u * 3u);
  im.set(-1, 0, {255, 0, 0});  // outside: nothing happens, no write past the buffer
  im.set(5, 3, {255, 0, 0});
  im.set(4, 3, {1, 2, 3});
  EXPECT_EQ(im.at(4, 3)[0], 1);
  EXPECT_EQ(im.at(4, 3)[2], 3);
  im.fillRect(3, -2, 99, 2, {0, 255, 0});  // [3, 5) x [0, 2) after clipping
  int green = 0;
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 5; ++x) green += im.at(x, y)[1] == 255;
  EXPECT_EQ(green, 4);
  EXPECT_EQ(im.at(2, 0)[1], 20);
}

TEST(RasterImage, PngRoundTripsEveryPixel) {
  RasterImage im(7, 5);
  for (int y = 0; y < 5; ++y)
    for (int x = 0; x < 7; ++x) im.set(x, y, {static_cast<std::uint8_t>(x * 30), static_cast<std::uint8_t>(y * 50), static_cast<std::uint8_t>(x * y)});
  const RasterImage back = testpng::decode(encodePng(im));
  EXPECT_EQ(back.width, 7);
  EXPECT_EQ(back.height, 5);
  EXPECT_EQ(back.rgb, im.rgb);
}

TEST(RasterImage, WritePngIsAtomicAndRefusesAFolderItCannotWrite) {
  RasterImage im(4, 3, {1, 2, 3});
  EXPECT_THROW(writePng(im, "/nonexistent-folder/x.png"), Error);
  const std::string path = testing::TempDir() + "/holefill_raster_test.png";
  writePng(im, path);
  std::ifstream f(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  EXPECT_EQ(testpng::decode(bytes).rgb, im.rgb);
  std::remove(path.c_str());
}

TEST(RasterImage, TextIsDrawnInTheFontsCellsAndLowerCaseAsUpper) {
  RasterImage a(80, 20), b(80, 20);
  const int w = drawText(a, 2, 3, "k=-1.5e-3", 2, {0, 0, 0});
  EXPECT_EQ(w, textWidth("k=-1.5e-3", 2));
  EXPECT_EQ(w, 9 * 6 * 2);
  drawText(b, 2, 3, "K=-1.5E-3", 2, {0, 0, 0});
  int inkA = 0;
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 80; ++x) {
      inkA += a.at(x, y)[0] == 0;
      if (x < 2 || y < 3 || y >= 3 + 14) EXPECT_EQ(a.at(x, y)[0], 255) << x << "," << y;  // inside its cells only
    }
  EXPECT_GT(inkA, 40);
  // "e" has its own glyph; "k" is drawn as "K".
  int sameK = 0;
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 14; ++x) sameK += a.at(x, y)[0] == b.at(x, y)[0];
  EXPECT_EQ(sameK, 20 * 14);
}

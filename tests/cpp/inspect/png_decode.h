// Test helper: the pixels of a PNG that encodePng wrote, decoded back (one IDAT, filter 0), with
// every chunk's CRC checked.
#pragma once

#include <gtest/gtest.h>
#include <zlib.h>

#include <algorithm>
#include <cstdint>
#include <string>

#include "inspect/raster_image.h"

namespace holefill::testpng {

inline RasterImage decode(const std::string& png) {
  EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  const auto be = [&](size_t at) {
    return (static_cast<std::uint32_t>(static_cast<unsigned char>(png[at])) << 24) |
           (static_cast<std::uint32_t>(static_cast<unsigned char>(png[at + 1])) << 16) |
           (static_cast<std::uint32_t>(static_cast<unsigned char>(png[at + 2])) << 8) | static_cast<unsigned char>(png[at + 3]);
  };
  RasterImage im(static_cast<int>(be(16)), static_cast<int>(be(20)));
  size_t at = 8;
  while (at < png.size()) {
    const std::uint32_t len = be(at);
    const std::string type = png.substr(at + 4, 4);
    const std::uint32_t crc = be(at + 8 + len);
    EXPECT_EQ(crc, crc32(0L, reinterpret_cast<const Bytef*>(png.data() + at + 4), len + 4)) << type;
    if (type == "IDAT") {
      uLongf n = (3 * im.width + 1) * im.height;
      std::string raw(n, '\0');
      EXPECT_EQ(uncompress(reinterpret_cast<Bytef*>(&raw[0]), &n, reinterpret_cast<const Bytef*>(png.data() + at + 8), len), Z_OK);
      for (int y = 0; y < im.height; ++y) std::copy_n(raw.begin() + y * (3 * im.width + 1) + 1, 3 * im.width, im.at(0, y));
    }
    at += 12 + len;
  }
  return im;
}

}  // namespace holefill::testpng

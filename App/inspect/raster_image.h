// An 8-bit RGB raster and its PNG encoding (zlib deflate, one IDAT chunk, no filter),
// plus a 5x7 bitmap font for the legend text, so inspection pictures are written by the
// core alone: no display, no GL, no FreeCAD. PNG writes are atomic (temporary file + rename).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace holefill {

struct RasterImage {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;  // row-major from the top row, 3 bytes per pixel

  RasterImage() = default;
  RasterImage(int w, int h, std::array<std::uint8_t, 3> fill = {255, 255, 255});
  std::uint8_t* at(int x, int y) { return &rgb[3 * (static_cast<size_t>(y) * width + x)]; }
  const std::uint8_t* at(int x, int y) const { return &rgb[3 * (static_cast<size_t>(y) * width + x)]; }
  void set(int x, int y, std::array<std::uint8_t, 3> c);  // ignores pixels outside
  void fillRect(int x0, int y0, int x1, int y1, std::array<std::uint8_t, 3> c);  // [x0, x1) x [y0, y1)
};

// PNG file bytes of the image.
std::string encodePng(const RasterImage& image);
// Writes PNG bytes atomically; throws holefill::Error when the folder is not writable.
void writePng(const RasterImage& image, const std::string& path);

// Text in the 5x7 font (digits, A-Z, "e", ".,-+=:/()[]_"; lower case is drawn upper case),
// top-left at (x, y), each font pixel `scale` pixels wide; returns the width drawn.
int drawText(RasterImage& image, int x, int y, const std::string& text, int scale, std::array<std::uint8_t, 3> color);
int textWidth(const std::string& text, int scale);

}  // namespace holefill

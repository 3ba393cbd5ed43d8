// RGBA8 images in memory, PNG files, and the pixel comparisons the tests and benchmarks use.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/result.h"

namespace reflect {

struct RgbaImage {
  int width = 0;
  int height = 0;
  std::vector<uint8_t> pixels;  // row-major, top row first, 4 bytes a pixel

  const uint8_t* at(int x, int y) const {
    return &pixels[(static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)) *
                   4];
  }
};

// GL reads rows bottom-up; images and PNGs are top-down.
void flipRows(RgbaImage& image);

// Fills the w x h rectangle at (x, y) with `rgba`; the part outside the image is left out.
void fillRect(RgbaImage& image, int x, int y, int w, int h, const std::array<uint8_t, 4>& rgba);

// The largest width or height decodeImage accepts by default (8192 x 8192 RGBA8 is 256 MB).
inline constexpr int kMaxImageDimension = 8192;

// Decodes a PNG file held in memory to RGBA8 (stb_image's other formats are refused: the project
// reads only PNG, and only the PNG decoder is fuzzed). Chunk lengths are checked against the
// data, and images wider or taller than `maxDimension` are rejected, before any pixel memory is
// allocated. `name` is used in every message (usually the path the bytes came from).
Result<RgbaImage> decodeImage(const uint8_t* data, size_t size, const std::string& name,
                              int maxDimension = kMaxImageDimension);
// Reads the file's bytes and decodes them with decodeImage.
Result<RgbaImage> readPng(const std::string& path);
// Returns an empty string on success, else a message naming the file.
std::string writePng(const RgbaImage& image, const std::string& path);

struct ImageDifference {
  int maxChannel = 0;      // largest absolute difference of any channel, 0..255
  double meanChannel = 0;  // mean absolute difference over RGB channels, 0..255
  double fractionOver =
      0;  // fraction of pixels with any RGB channel differing by more than the tolerance
};

// Compares RGB only (alpha is always opaque here). Images must have the same size.
Result<ImageDifference> compareImages(const RgbaImage& a, const RgbaImage& b, int tolerance = 0);

}  // namespace reflect

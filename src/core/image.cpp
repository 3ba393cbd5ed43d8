#include "core/image.h"

#include <stb_image.h>
#include <stb_image_write.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>

namespace reflect {

void flipRows(RgbaImage& image) {
  const size_t rowBytes = static_cast<size_t>(image.width) * 4;
  std::vector<uint8_t> row(rowBytes);
  for (int y = 0; y < image.height / 2; ++y) {
    uint8_t* top = &image.pixels[static_cast<size_t>(y) * rowBytes];
    uint8_t* bottom = &image.pixels[static_cast<size_t>(image.height - 1 - y) * rowBytes];
    std::memcpy(row.data(), top, rowBytes);
    std::memcpy(top, bottom, rowBytes);
    std::memcpy(bottom, row.data(), rowBytes);
  }
}

Result<RgbaImage> readPng(const std::string& path) {
  int w = 0, h = 0, channels = 0;
  stbi_uc* data = stbi_load(path.c_str(), &w, &h, &channels, 4);
  if (!data) {
    return Result<RgbaImage>::failure(path + ": cannot read image (" + stbi_failure_reason() + ")");
  }
  RgbaImage image;
  image.width = w;
  image.height = h;
  image.pixels.assign(data, data + static_cast<size_t>(w) * static_cast<size_t>(h) * 4);
  stbi_image_free(data);
  return image;
}

std::string writePng(const RgbaImage& image, const std::string& path) {
  if (!stbi_write_png(path.c_str(), image.width, image.height, 4, image.pixels.data(),
                      image.width * 4)) {
    return path + ": cannot write PNG";
  }
  return {};
}

Result<ImageDifference> compareImages(const RgbaImage& a, const RgbaImage& b, int tolerance) {
  if (a.width != b.width || a.height != b.height) {
    return Result<ImageDifference>::failure(
        "image sizes differ: " + std::to_string(a.width) + "x" + std::to_string(a.height) +
        " vs " + std::to_string(b.width) + "x" + std::to_string(b.height));
  }
  ImageDifference d;
  const size_t pixelCount = static_cast<size_t>(a.width) * static_cast<size_t>(a.height);
  double sum = 0;
  size_t over = 0;
  for (size_t p = 0; p < pixelCount; ++p) {
    int worst = 0;
    for (size_t c = 0; c < 3; ++c) {
      int diff = std::abs(int(a.pixels[p * 4 + c]) - int(b.pixels[p * 4 + c]));
      sum += diff;
      worst = std::max(worst, diff);
    }
    d.maxChannel = std::max(d.maxChannel, worst);
    if (worst > tolerance) ++over;
  }
  if (pixelCount > 0) {
    d.meanChannel = sum / double(pixelCount * 3);
    d.fractionOver = double(over) / double(pixelCount);
  }
  return d;
}

}  // namespace reflect

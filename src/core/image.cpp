#include "core/image.h"

#include <stb_image.h>
#include <stb_image_write.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>

namespace reflect {
namespace {

constexpr uint8_t kPngSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

uint32_t readBigEndian32(const uint8_t* p) {
  return (uint32_t{p[0]} << 24) | (uint32_t{p[1]} << 16) | (uint32_t{p[2]} << 8) | uint32_t{p[3]};
}

// stb_image trusts chunk lengths: a 100-byte file whose IDAT claims a gigabyte makes it allocate
// one. Walks the chunks up to IEND and returns "" or what is wrong.
std::string checkPngChunks(const uint8_t* data, size_t size) {
  size_t pos = sizeof(kPngSignature);
  while (pos < size) {
    if (size - pos < 12) return "truncated chunk header";
    const size_t length = readBigEndian32(data + pos);
    const std::string type(reinterpret_cast<const char*>(data + pos + 4), 4);
    if (length > size - pos - 12) {
      return "chunk of " + std::to_string(length) + " bytes runs past the end of the file";
    }
    if (type == "IEND") return {};
    pos += 12 + length;
  }
  return "no IEND chunk";
}

std::string decodeFailure() {
  const char* reason = stbi_failure_reason();
  return reason ? reason : "unknown reason";
}

}  // namespace

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

void fillRect(RgbaImage& image, int x, int y, int w, int h, const std::array<uint8_t, 4>& rgba) {
  const int x0 = std::max(x, 0);
  const int x1 = std::min(x + w, image.width);
  for (int row = std::max(y, 0); row < std::min(y + h, image.height); ++row) {
    for (int column = x0; column < x1; ++column) {
      std::memcpy(&image.pixels[(static_cast<size_t>(row) * static_cast<size_t>(image.width) +
                                 static_cast<size_t>(column)) *
                                4],
                  rgba.data(), 4);
    }
  }
}

Result<RgbaImage> decodeImage(const uint8_t* data, size_t size, const std::string& name,
                              int maxDimension) {
  if (size == 0) return Result<RgbaImage>::failure(name + ": cannot read image (empty file)");
  if (size > static_cast<size_t>(std::numeric_limits<int>::max())) {
    return Result<RgbaImage>::failure(name + ": cannot read image (file of " +
                                      std::to_string(size) + " bytes is too large)");
  }
  if (size < sizeof(kPngSignature) ||
      std::memcmp(data, kPngSignature, sizeof(kPngSignature)) != 0) {
    return Result<RgbaImage>::failure(name + ": cannot read image (not a PNG file)");
  }
  const std::string chunkProblem = checkPngChunks(data, size);
  if (!chunkProblem.empty()) {
    return Result<RgbaImage>::failure(name + ": cannot read image (" + chunkProblem + ")");
  }
  const int length = static_cast<int>(size);
  int w = 0, h = 0, channels = 0;
  // The header first: a huge image is rejected before its pixels are allocated.
  if (!stbi_info_from_memory(data, length, &w, &h, &channels)) {
    return Result<RgbaImage>::failure(name + ": cannot read image (" + decodeFailure() + ")");
  }
  if (w < 1 || h < 1 || w > maxDimension || h > maxDimension) {
    return Result<RgbaImage>::failure(
        name + ": image is " + std::to_string(w) + "x" + std::to_string(h) +
        ", over the limit of " + std::to_string(maxDimension) + "x" + std::to_string(maxDimension));
  }
  stbi_uc* pixels = stbi_load_from_memory(data, length, &w, &h, &channels, 4);
  if (!pixels) {
    return Result<RgbaImage>::failure(name + ": cannot read image (" + decodeFailure() + ")");
  }
  // The decoder reads the header again; trust only sizes within the limit checked above.
  if (w < 1 || h < 1 || w > maxDimension || h > maxDimension) {
    stbi_image_free(pixels);
    return Result<RgbaImage>::failure(name + ": cannot read image (inconsistent header)");
  }
  RgbaImage image;
  image.width = w;
  image.height = h;
  image.pixels.assign(pixels, pixels + static_cast<size_t>(w) * static_cast<size_t>(h) * 4);
  stbi_image_free(pixels);
  return image;
}

Result<RgbaImage> readPng(const std::string& path) {
  std::ifstream file(path, std::ios::binary | std::ios::ate);
  if (!file) return Result<RgbaImage>::failure(path + ": cannot read image (cannot open file)");
  const std::streamoff size = file.tellg();
  if (size < 0) return Result<RgbaImage>::failure(path + ": cannot read image (cannot read file)");
  std::vector<uint8_t> bytes(static_cast<size_t>(size));
  file.seekg(0);
  if (!file.read(reinterpret_cast<char*>(bytes.data()), size)) {
    return Result<RgbaImage>::failure(path + ": cannot read image (cannot read file)");
  }
  return decodeImage(bytes.data(), bytes.size(), path);
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
        "image sizes differ: " + std::to_string(a.width) + "x" + std::to_string(a.height) + " vs " +
        std::to_string(b.width) + "x" + std::to_string(b.height));
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

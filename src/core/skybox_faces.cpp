#include "core/skybox_faces.h"

#include <cstring>

namespace reflect {

std::array<std::string, 6> skyboxSuffixPaths(const std::string& path) {
  const size_t dot = path.find_last_of('.');
  const size_t slash = path.find_last_of('/');
  const bool hasExtension = dot != std::string::npos && (slash == std::string::npos || dot > slash);
  const std::string stem = hasExtension ? path.substr(0, dot) : path;
  const std::string extension = hasExtension ? path.substr(dot) : ".png";
  const char* suffixes[6] = {"_px", "_nx", "_py", "_ny", "_pz", "_nz"};
  std::array<std::string, 6> paths;
  for (size_t i = 0; i < 6; ++i) paths[i] = stem + suffixes[i] + extension;
  return paths;
}

Result<CubeFaces> facesFromImages(std::vector<RgbaImage> images,
                                  const std::array<std::string, 6>& names) {
  if (images.size() != 6) {
    return Result<CubeFaces>::failure("a skybox needs 6 images, got " +
                                      std::to_string(images.size()));
  }
  CubeFaces faces;
  for (size_t i = 0; i < 6; ++i) {
    const RgbaImage& image = images[i];
    const std::string size = std::to_string(image.width) + "x" + std::to_string(image.height);
    if (image.width < 1 || image.width != image.height) {
      return Result<CubeFaces>::failure(names[i] + ": a cube face must be square, this image is " +
                                        size);
    }
    if (image.width != images[0].width) {
      return Result<CubeFaces>::failure(names[i] + ": is " + size + " but " + names[0] + " is " +
                                        std::to_string(images[0].width) + "x" +
                                        std::to_string(images[0].height) +
                                        "; all six faces must be the same size");
    }
    faces[i] = std::move(images[i]);
  }
  return faces;
}

Result<CubeFaces> facesFromCross(const RgbaImage& cross, const std::string& name) {
  if (cross.width < 4 || cross.width * 3 != cross.height * 4 || cross.width % 4 != 0) {
    return Result<CubeFaces>::failure(
        name + ": a horizontal cross must be 4:3 with whole squares (4n x 3n), this image is " +
        std::to_string(cross.width) + "x" + std::to_string(cross.height));
  }
  const int n = cross.width / 4;
  CubeFaces faces;
  for (size_t f = 0; f < 6; ++f) {
    RgbaImage& face = faces[f];
    face.width = face.height = n;
    face.pixels.resize(static_cast<size_t>(n) * static_cast<size_t>(n) * 4);
    for (int y = 0; y < n; ++y) {
      const uint8_t* row = cross.at(kCrossCells[f][0] * n, kCrossCells[f][1] * n + y);
      std::memcpy(&face.pixels[static_cast<size_t>(y) * static_cast<size_t>(n) * 4], row,
                  static_cast<size_t>(n) * 4);
    }
  }
  return faces;
}

uint64_t contentHash(const CubeFaces& faces) {
  uint64_t hash = 14695981039346656037ull;
  const auto mix = [&hash](uint64_t byte) {
    hash ^= byte;
    hash *= 1099511628211ull;
  };
  for (const RgbaImage& face : faces) {
    mix(static_cast<uint64_t>(face.width));
    mix(static_cast<uint64_t>(face.height));
    for (uint8_t byte : face.pixels) mix(byte);
  }
  return hash == 0 ? 1 : hash;
}

}  // namespace reflect

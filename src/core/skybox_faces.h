// The six square images of a static cube map, checked and in GL face order (+X, -X, +Y, -Y, +Z,
// -Z), from six separate images or one horizontal cross. Not flipped: cube-map faces are
// addressed top row first, as images are stored.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/image.h"
#include "core/result.h"

namespace reflect {

using CubeFaces = std::array<RgbaImage, 6>;

// The six paths of a skybox named by one path and the suffixes _px _nx _py _ny _pz _nz:
// "sky/day.png" -> "sky/day_px.png", ...
std::array<std::string, 6> skyboxSuffixPaths(const std::string& path);

// Six images (names for messages): equal, non-empty squares.
Result<CubeFaces> facesFromImages(std::vector<RgbaImage> images,
                                  const std::array<std::string, 6>& names);

// One horizontal cross, 4 squares wide and 3 high:
//        [+Y]
//   [-X] [+Z] [+X] [-Z]
//        [-Y]
Result<CubeFaces> facesFromCross(const RgbaImage& cross, const std::string& name);

// (column, row) of each face's square in that cross, in GL face order: the one layout both
// facesFromCross and the faces view (core/cube_cross.h) use.
inline constexpr std::array<std::array<int, 2>, 6> kCrossCells{
    {{{2, 1}}, {{0, 1}}, {{1, 0}}, {{1, 2}}, {{1, 1}}, {{3, 1}}}};

// A 64-bit FNV-1a hash of the faces' sizes and pixels: two skyboxes with the same pixels hash the
// same, so a capture can tell by value whether the sky it shows changed. Never 0.
uint64_t contentHash(const CubeFaces& faces);

}  // namespace reflect

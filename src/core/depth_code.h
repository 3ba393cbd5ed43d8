// The 16-bit depth code captures store for the hierarchical search, as the C++ side needs it (the
// clear value of a face: the far plane). The same formula is GLSL's encodeDepth in
// shaders/depth_encoding.glsl; a GL test reads a captured face back and holds the two equal.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace reflect {

inline constexpr uint32_t kInfiniteDepthCode = 65535;

// `z`: depth along the face's look direction in units of the capture's near plane (>= 1).
inline uint32_t depthCode(double z) {
  const double e = 1.0 - 1.0 / std::max(z, 1.0);
  return static_cast<uint32_t>(std::clamp(std::floor(e * 65535.0 + 0.5), 0.0, 65534.0));
}

}  // namespace reflect

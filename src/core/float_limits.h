// The float infinity the ray code starts its nearest-hit searches from, named once.
#pragma once

#include <limits>

namespace reflect {

inline constexpr float kInfinity = std::numeric_limits<float>::infinity();

}  // namespace reflect

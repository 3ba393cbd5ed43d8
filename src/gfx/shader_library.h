// The GLSL files of shaders/, embedded into the binary at build time (see
// cmake/EmbedShaders.cmake), so neither the page nor the CLI reads shader paths at run time.
#pragma once

#include <string_view>

namespace reflect {

// The text of shaders/<fileName>, without the #version line; nullptr if there is no such file.
const char* embeddedShader(std::string_view fileName);

}  // namespace reflect

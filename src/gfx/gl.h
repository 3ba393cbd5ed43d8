// The one include for GL ES 3.0, the API shared by WebGL2 (through Emscripten) and native EGL.
// Call nothing beyond ES 3.0: native Mesa offers 3.2, the browser does not.
#pragma once

#include <GLES3/gl3.h>

namespace reflect {

// Reports any pending GL error with `where` to stderr and returns false. Native and debug builds
// check; optimised web builds skip it, because glGetError stalls a WebGL pipeline.
bool checkGlError(const char* where);

}  // namespace reflect

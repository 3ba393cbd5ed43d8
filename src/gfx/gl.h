// The one include for GL ES 3.0, the API shared by WebGL2 (through Emscripten) and native EGL.
// Call nothing beyond ES 3.0: native Mesa offers 3.2, the browser does not.
#pragma once

#include <GLES3/gl3.h>

namespace reflect {

// Reports any pending GL error with `where` to stderr and returns false. Native and debug builds
// check; optimised web builds skip it, because glGetError stalls a WebGL pipeline.
bool checkGlError(const char* where);

// Blocks until the GPU has finished everything submitted so far. glFinish alone does not wait in
// every WebGL implementation; reading one pixel back does, natively and in the browser.
void waitForGpu();

}  // namespace reflect

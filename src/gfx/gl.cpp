#include "gfx/gl.h"

#include <cstdio>

namespace reflect {

bool checkGlError(const char* where) {
#if defined(__EMSCRIPTEN__) && defined(NDEBUG)
  (void)where;
  return true;
#else
  bool ok = true;
  for (GLenum e = glGetError(); e != GL_NO_ERROR; e = glGetError()) {
    std::fprintf(stderr, "GL error 0x%04x at %s\n", e, where);
    ok = false;
  }
  return ok;
#endif
}

}  // namespace reflect

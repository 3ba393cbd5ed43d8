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

void waitForGpu() {
#if defined(__EMSCRIPTEN__)
  // WebGL's finish() returns before the GPU process is done; a read back cannot.
  // The canvas (framebuffer 0) always exists on the web, so bind it for the read.
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  GLubyte pixel[4];
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel);
#else
  // Natively there is no default framebuffer (EGL surfaceless), and Mesa's glFinish does wait.
  glFinish();
#endif
}

}  // namespace reflect

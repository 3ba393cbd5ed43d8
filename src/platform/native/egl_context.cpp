#include "platform/native/egl_context.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include "gfx/gl.h"

namespace reflect {
namespace {

std::string eglFailure(const char* step) {
  char code[16];
  std::snprintf(code, sizeof code, "0x%04x", eglGetError());
  return std::string("EGL: ") + step + " failed (" + code + ")";
}

// The first EGL device's display (EGL_EXT_platform_device): what a vendor driver without Mesa's
// surfaceless platform (NVIDIA's) offers for rendering with no window system.
EGLDisplay firstDeviceDisplay(PFNEGLGETPLATFORMDISPLAYEXTPROC getPlatformDisplay) {
  auto queryDevices =
      reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
  EGLDeviceEXT device = nullptr;
  EGLint count = 0;
  if (!queryDevices || !queryDevices(1, &device, &count) || count < 1) return EGL_NO_DISPLAY;
  return getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, device, nullptr);
}

// Mesa's surfaceless platform (llvmpipe here, or a Mesa GPU driver), else the first device.
Result<EGLDisplay> openDisplay() {
  auto getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
      eglGetProcAddress("eglGetPlatformDisplayEXT"));
  if (!getPlatformDisplay) {
    return Result<EGLDisplay>::failure("EGL: eglGetPlatformDisplayEXT is not available");
  }
  EGLDisplay display =
      getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (display != EGL_NO_DISPLAY && eglInitialize(display, nullptr, nullptr)) return display;
  const std::string surfaceless = eglFailure("the surfaceless display");
  display = firstDeviceDisplay(getPlatformDisplay);
  if (display != EGL_NO_DISPLAY && eglInitialize(display, nullptr, nullptr)) return display;
  return Result<EGLDisplay>::failure(surfaceless + "; " + eglFailure("the first device's display"));
}

}  // namespace

Result<std::unique_ptr<HeadlessGlContext>> HeadlessGlContext::create() {
  using Out = Result<std::unique_ptr<HeadlessGlContext>>;
  Result<EGLDisplay> opened = openDisplay();
  if (!opened) return Out::failure(opened.error());
  EGLDisplay display = opened.value();
  if (!eglBindAPI(EGL_OPENGL_ES_API)) return Out::failure(eglFailure("eglBindAPI"));

  const EGLint configAttributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_ES3_BIT, EGL_SURFACE_TYPE,
                                     EGL_PBUFFER_BIT, EGL_NONE};
  EGLConfig config = nullptr;
  EGLint configCount = 0;
  if (!eglChooseConfig(display, configAttributes, &config, 1, &configCount) || configCount < 1) {
    return Out::failure(eglFailure("eglChooseConfig (GL ES 3)"));
  }
  const EGLint contextAttributes[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 0,
                                      EGL_NONE};
  EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, contextAttributes);
  if (context == EGL_NO_CONTEXT) return Out::failure(eglFailure("eglCreateContext (ES 3.0)"));
  if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
    eglDestroyContext(display, context);
    return Out::failure(eglFailure("eglMakeCurrent (surfaceless)"));
  }
  std::unique_ptr<HeadlessGlContext> result(new HeadlessGlContext());
  result->display_ = display;
  result->context_ = context;
  return Out(std::move(result));
}

HeadlessGlContext::~HeadlessGlContext() {
  eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(display_, context_);
  eglTerminate(display_);
}

std::string HeadlessGlContext::description() const {
  auto text = [](GLenum name) {
    const GLubyte* s = glGetString(name);
    return s ? std::string(reinterpret_cast<const char*>(s)) : std::string("?");
  };
  return text(GL_VERSION) + " | " + text(GL_RENDERER);
}

}  // namespace reflect

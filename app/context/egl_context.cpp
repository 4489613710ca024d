// EGL without a window: an enumerated device first (the GPU on an NVIDIA server, llvmpipe on
// Mesa), then Mesa's surfaceless platform. eglGetDisplay(EGL_DEFAULT_DISPLAY) needs X, so we
// never use it.
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <vector>

#include "app/context/gl_context.h"
#include "app/gl/load_gl.h"

namespace shadelab {
namespace {

ShlGlProc eglProc(const char* name) { return reinterpret_cast<ShlGlProc>(eglGetProcAddress(name)); }

class EglContext final : public GlContext {
 public:
  EglContext(EGLDisplay d, EGLContext c) : display_(d), context_(c) {}
  ~EglContext() override {
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display_, context_);
    eglTerminate(display_);
  }
  void makeCurrent() override { eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_); }

 private:
  EGLDisplay display_;
  EGLContext context_;
};

std::vector<EGLDisplay> candidateDisplays() {
  std::vector<EGLDisplay> out;
  auto getPlatformDisplay =
      reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
  auto queryDevices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
  if (!getPlatformDisplay) return out;
  if (queryDevices) {
    EGLDeviceEXT devices[8];
    EGLint count = 0;
    if (queryDevices(8, devices, &count))
      for (EGLint i = 0; i < count; ++i)
        if (EGLDisplay d = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr)) out.push_back(d);
  }
  if (EGLDisplay d = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr)) out.push_back(d);
  return out;
}

EGLContext createCoreContext(EGLDisplay display) {
  EGLint major = 0, minor = 0;
  if (!eglInitialize(display, &major, &minor)) return EGL_NO_CONTEXT;
  if (!eglBindAPI(EGL_OPENGL_API)) return EGL_NO_CONTEXT;
  const EGLint configAttribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
  EGLConfig config;
  EGLint n = 0;
  if (!eglChooseConfig(display, configAttribs, &config, 1, &n) || n < 1) config = nullptr;
  for (const gl::Version v : gl::kContextVersions) {
    const EGLint ctxAttribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                                 v.major,
                                 EGL_CONTEXT_MINOR_VERSION,
                                 v.minor,
                                 EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                 EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                 EGL_NONE};
    EGLContext ctx = eglCreateContext(display, config, EGL_NO_CONTEXT, ctxAttribs);
    if (ctx != EGL_NO_CONTEXT && eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx)) return ctx;
    if (ctx != EGL_NO_CONTEXT) eglDestroyContext(display, ctx);
  }
  eglTerminate(display);
  return EGL_NO_CONTEXT;
}

}  // namespace

std::unique_ptr<GlContext> createEglContext(std::string& error) {
  for (EGLDisplay display : candidateDisplays()) {
    EGLContext ctx = createCoreContext(display);
    if (ctx == EGL_NO_CONTEXT) continue;
    auto context = std::make_unique<EglContext>(display, ctx);
    const char* missing = "";
    if (gl::loadFunctions(eglProc, &missing)) return context;
    error = std::string("egl: the context lacks core function ") + missing;
    return nullptr;
  }
  error = "egl: no device or surfaceless display gave an OpenGL 3.3 core context (install libegl-mesa0)";
  return nullptr;
}

}  // namespace shadelab

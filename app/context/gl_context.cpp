#include "app/context/gl_context.h"

#include "app/gl/gl.h"

namespace shadelab {

std::string GlContext::describe() const {
  auto str = [](GLenum e) {
    const GLubyte* s = glGetString(e);
    return s ? std::string(reinterpret_cast<const char*>(s)) : std::string("?");
  };
  return str(GL_RENDERER) + ", OpenGL " + str(GL_VERSION);
}

std::unique_ptr<GlContext> createHeadlessContext(std::string_view backend, std::string& error) {
  if (backend == "osmesa") {
#ifdef SHADELAB_HAS_OSMESA
    return createOsMesaContext(error);
#else
    error = "osmesa: this build has no OSMesa back end (configured with SHADELAB_OSMESA=OFF); use --backend egl";
    return nullptr;
#endif
  }
  if (backend == "egl") return createEglContext(error);
  error = "unknown backend '" + std::string(backend) + "' (valid: " + std::string(kHeadlessBackends) + ")";
  return nullptr;
}

}  // namespace shadelab

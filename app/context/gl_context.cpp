#include "context/gl_context.h"

#include "gl/gl.h"

namespace shadelab {

std::string GlContext::describe() const {
  auto str = [](GLenum e) {
    const GLubyte* s = glGetString(e);
    return s ? std::string(reinterpret_cast<const char*>(s)) : std::string("?");
  };
  return str(GL_RENDERER) + ", OpenGL " + str(GL_VERSION);
}

std::unique_ptr<GlContext> createHeadlessContext(std::string_view backend, std::string& error) {
  if (backend == "osmesa") return createOsMesaContext(error);
  if (backend == "egl") return createEglContext(error);
  error = "unknown backend '" + std::string(backend) + "' (valid: " + std::string(kHeadlessBackends) + ")";
  return nullptr;
}

}  // namespace shadelab

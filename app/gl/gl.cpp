#include "app/gl/gl.h"

#include <cstring>
#include <string>

namespace gl {

bool loadFunctions(ShlGetProcAddress getProc, const char** missing) {
  shlLoadGL(getProc);
  // A handful of functions are enough to tell a usable 3.3+ core context from a broken one;
  // later-version entry points may legitimately be absent on older drivers.
  const bool usable = glGetString && glGenVertexArrays && glCreateShader && glGenQueries && glTexImage2D;
  if (!usable && missing) *missing = shlFirstMissingGL();
  return usable;
}

bool rendererIs(const char* name) {
  const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  return renderer && std::strstr(renderer, name);
}

bool softwareRenderer() { return rendererIs("llvmpipe") || rendererIs("softpipe") || rendererIs("SwiftShader"); }

bool esContext() {
  const char* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  return version && (std::strstr(version, "OpenGL ES") || std::strstr(version, "WebGL"));
}

bool hasGeometryShaders() { return !esContext(); }

bool hasBorderColor() { return !esContext(); }

bool hasNorm16Textures() { return !esContext(); }

bool hasTessellation() {
  GLint major = 0, minor = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  return major >= 4 && glPatchParameteri != nullptr;
}

const char* errorString(GLenum error) {
  switch (error) {
    case GL_INVALID_ENUM:
      return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE:
      return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION:
      return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION:
      return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY:
      return "GL_OUT_OF_MEMORY";
    case GL_STACK_OVERFLOW:
      return "GL_STACK_OVERFLOW";
    case GL_STACK_UNDERFLOW:
      return "GL_STACK_UNDERFLOW";
    default:
      return "GL_UNKNOWN_ERROR";
  }
}

std::string drainErrors() {
  std::string out;
  for (int i = 0; i < 16; ++i) {  // bounded: a lost context can report errors forever
    GLenum e = glGetError();
    if (e == GL_NO_ERROR) break;
    if (!out.empty()) out += ", ";
    out += errorString(e);
  }
  return out;
}

}  // namespace gl

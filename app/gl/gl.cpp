#include "gl/gl.h"

#include <cstring>

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
    case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
    case GL_STACK_OVERFLOW: return "GL_STACK_OVERFLOW";
    case GL_STACK_UNDERFLOW: return "GL_STACK_UNDERFLOW";
    default: return "GL_UNKNOWN_ERROR";
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

void releaseDriverHeldTextures() {
  // Big enough that every rasteriser thread gets tiles of it (llvmpipe's threads hold their own);
  // one byte a texel, since the driver then holds these (3 MB; RGBA8 was 11 MB, and whether the
  // driver held them or the next lab's own came and went with the threads: a step of 11 MB on
  // some lab entries and not others in the window's soak).
  constexpr int kSide = 512;
  GLuint texture[2] = {0, 0}, framebuffer = 0;
  glGenTextures(2, texture);
  glBindTexture(GL_TEXTURE_2D, texture[0]);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_R8, kSide, kSide, 0, GL_RED, GL_UNSIGNED_BYTE, nullptr);
  glBindTexture(GL_TEXTURE_2D, 0);
  glGenFramebuffers(1, &framebuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture[0], 0);
  GLint viewport[4];
  glGetIntegerv(GL_VIEWPORT, viewport);
  glViewport(0, 0, kSide, kSide);
  glClear(GL_COLOR_BUFFER_BIT);
  glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDeleteFramebuffers(1, &framebuffer);

  constexpr int kLayers = 8, kLevels = 3;  // as many layers as a lab's arrays have (cascades: 4)
  glBindTexture(GL_TEXTURE_2D_ARRAY, texture[1]);
  for (int level = 0; level < kLevels; ++level)
    glTexImage3D(GL_TEXTURE_2D_ARRAY, level, GL_R8, kSide >> level, kSide >> level, kLayers, 0, GL_RED, GL_UNSIGNED_BYTE,
                 nullptr);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAX_LEVEL, kLevels - 1);
  glGenerateMipmap(GL_TEXTURE_2D_ARRAY);
  glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
  glDeleteTextures(2, texture);
}

}  // namespace gl

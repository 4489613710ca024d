#include "app/gl/handle.h"

#include <array>
#include <atomic>

namespace gl {
namespace {
std::array<std::atomic<int>, static_cast<size_t>(Kind::Count)> g_live{};
}

GLuint create(Kind kind, GLenum shaderType) {
  GLuint n = 0;
  switch (kind) {
    case Kind::Buffer:
      glGenBuffers(1, &n);
      break;
    case Kind::VertexArray:
      glGenVertexArrays(1, &n);
      break;
    case Kind::Texture:
      glGenTextures(1, &n);
      break;
    case Kind::Framebuffer:
      glGenFramebuffers(1, &n);
      break;
    case Kind::Renderbuffer:
      glGenRenderbuffers(1, &n);
      break;
    case Kind::Program:
      n = glCreateProgram();
      break;
    case Kind::Shader:
      n = glCreateShader(shaderType);
      break;
    case Kind::Query:
      glGenQueries(1, &n);
      break;
    case Kind::Sampler:
      glGenSamplers(1, &n);
      break;
    case Kind::Count:
      break;
  }
  if (n) ++g_live[static_cast<size_t>(kind)];
  return n;
}

void destroy(Kind kind, GLuint n) {
  switch (kind) {
    case Kind::Buffer:
      glDeleteBuffers(1, &n);
      break;
    case Kind::VertexArray:
      glDeleteVertexArrays(1, &n);
      break;
    case Kind::Texture:
      glDeleteTextures(1, &n);
      break;
    case Kind::Framebuffer:
      glDeleteFramebuffers(1, &n);
      break;
    case Kind::Renderbuffer:
      glDeleteRenderbuffers(1, &n);
      break;
    case Kind::Program:
      glDeleteProgram(n);
      break;
    case Kind::Shader:
      glDeleteShader(n);
      break;
    case Kind::Query:
      glDeleteQueries(1, &n);
      break;
    case Kind::Sampler:
      glDeleteSamplers(1, &n);
      break;
    case Kind::Count:
      return;
  }
  --g_live[static_cast<size_t>(kind)];
}

int liveObjects(Kind kind) { return g_live[static_cast<size_t>(kind)]; }

int liveObjectsTotal() {
  int total = 0;
  for (auto& c : g_live) total += c;
  return total;
}

const char* kindName(Kind kind) {
  static const char* names[] = {"buffer",  "vertex array", "texture", "framebuffer", "renderbuffer",
                                "program", "shader",       "query",   "sampler"};
  return kind < Kind::Count ? names[static_cast<size_t>(kind)] : "?";
}

}  // namespace gl

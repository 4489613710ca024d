// RAII ownership of OpenGL object names. Every name is counted while it lives, so tests can
// prove that a lab leaves no GL objects behind once it is destroyed.
#pragma once
#include <utility>

#include "app/gl/gl.h"

namespace gl {

enum class Kind { Buffer, VertexArray, Texture, Framebuffer, Renderbuffer, Program, Shader, Query, Sampler, Count };

GLuint create(Kind kind, GLenum shaderType = 0);
void destroy(Kind kind, GLuint name);
int liveObjects(Kind kind);
int liveObjectsTotal();
const char* kindName(Kind kind);

template <Kind K>
class Handle {
 public:
  Handle() = default;
  static Handle make(GLenum shaderType = 0) { return Handle(create(K, shaderType)); }
  ~Handle() { reset(); }
  Handle(Handle&& o) noexcept : name_(std::exchange(o.name_, 0)) {}
  Handle& operator=(Handle&& o) noexcept {
    if (this != &o) {
      reset();
      name_ = std::exchange(o.name_, 0);
    }
    return *this;
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;

  GLuint get() const { return name_; }
  explicit operator bool() const { return name_ != 0; }
  void reset() {
    if (name_) destroy(K, std::exchange(name_, 0));
  }

 private:
  explicit Handle(GLuint name) : name_(name) {}
  GLuint name_ = 0;
};

using Buffer = Handle<Kind::Buffer>;
using VertexArray = Handle<Kind::VertexArray>;
using TextureName = Handle<Kind::Texture>;
using FramebufferName = Handle<Kind::Framebuffer>;
using Renderbuffer = Handle<Kind::Renderbuffer>;
using ProgramName = Handle<Kind::Program>;
using ShaderName = Handle<Kind::Shader>;
using Query = Handle<Kind::Query>;
using Sampler = Handle<Kind::Sampler>;

}  // namespace gl

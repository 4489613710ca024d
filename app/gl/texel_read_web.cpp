// The page's texel read: at once, into the program's own memory (texel_read.h says why).
#include "app/gl/texel_read.h"

#include "app/gl/gl.h"

namespace gl {

TexelRead::~TexelRead() = default;

bool TexelRead::start(GLuint fbo, int x, int y) {
  if (inFlight_) return false;
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glReadPixels(x, y, 1, 1, GL_RGBA, GL_FLOAT, texel_.data());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  inFlight_ = true;
  return true;
}

std::optional<std::array<float, 4>> TexelRead::take() {
  if (!inFlight_) return std::nullopt;
  inFlight_ = false;
  return texel_;
}

}  // namespace gl

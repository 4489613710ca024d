// The desktop's texel read: a pixel buffer and a fence, polled (texel_read.h).
#include "app/gl/texel_read.h"

#include "app/gl/gl.h"

namespace gl {

TexelRead::~TexelRead() {
  if (fence_) glDeleteSync(fence_);
}

bool TexelRead::start(GLuint fbo, int x, int y) {
  if (inFlight_) return false;
  if (!buffer_) {
    buffer_ = Buffer::make();
    glBindBuffer(GL_PIXEL_PACK_BUFFER, buffer_.get());
    glBufferData(GL_PIXEL_PACK_BUFFER, sizeof(float) * 4, nullptr, GL_STREAM_READ);
  }
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, buffer_.get());
  glReadPixels(x, y, 1, 1, GL_RGBA, GL_FLOAT, nullptr);  // into the buffer: no wait
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  fence_ = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
  inFlight_ = true;
  return true;
}

std::optional<std::array<float, 4>> TexelRead::take() {
  if (!inFlight_) return std::nullopt;
  const GLenum state = fence_ ? glClientWaitSync(fence_, 0, 0) : GLenum(GL_WAIT_FAILED);  // a poll
  if (state == GL_TIMEOUT_EXPIRED) return std::nullopt;
  if (fence_) glDeleteSync(fence_);
  fence_ = nullptr;
  inFlight_ = false;  // arrived, or the wait failed: either way this read is done
  if (state != GL_ALREADY_SIGNALED && state != GL_CONDITION_SATISFIED) return std::nullopt;
  glBindBuffer(GL_PIXEL_PACK_BUFFER, buffer_.get());
  glGetBufferSubData(GL_PIXEL_PACK_BUFFER, 0, sizeof(float) * 4, texel_.data());
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  return texel_;
}

}  // namespace gl

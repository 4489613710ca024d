#include "app/gl/pixel_probe.h"

#include "app/context/load_gl.h"

namespace shadelab {

PixelProbe::~PixelProbe() {
  if (fence_) glDeleteSync(fence_);
}

void PixelProbe::request(const gl::RenderTarget& target, int x, int y) {
  if (fence_ || x < 0 || y < 0 || x >= target.size().x || y >= target.size().y) return;
  if (!buffer_) {
    buffer_ = gl::Buffer::make();
    glBindBuffer(GL_PIXEL_PACK_BUFFER, buffer_.get());
    glBufferData(GL_PIXEL_PACK_BUFFER, sizeof(float) * 4, nullptr, GL_STREAM_READ);
  }
  glBindFramebuffer(GL_READ_FRAMEBUFFER, target.fbo());
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, buffer_.get());
  glReadPixels(x, target.size().y - 1 - y, 1, 1, GL_RGBA, GL_FLOAT, nullptr);  // into the buffer: no wait
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  fence_ = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
  pending_ = {x, y, {}};
}

const std::optional<PixelProbe::Value>& PixelProbe::latest() {
  if (fence_) {
    const GLenum state = glClientWaitSync(fence_, 0, 0);  // a poll: a timeout of zero
    if (state == GL_ALREADY_SIGNALED || state == GL_CONDITION_SATISFIED) {
      glBindBuffer(GL_PIXEL_PACK_BUFFER, buffer_.get());
      glGetBufferSubData(GL_PIXEL_PACK_BUFFER, 0, sizeof(float) * 4, pending_.rgba.data());
      glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
      latest_ = pending_;
    }
    if (state != GL_TIMEOUT_EXPIRED) {  // arrived, or the wait failed: either way this fence is done
      glDeleteSync(fence_);
      fence_ = nullptr;
    }
  }
  return latest_;
}

}  // namespace shadelab

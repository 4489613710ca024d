// Reading a render target on the page: WebGL2 cannot map a buffer for reading (emscripten maps
// for writing only), so the bytes are read into memory of the program's own.
#include "app/gl/gl.h"
#include "app/gl/texture.h"

#include <vector>

namespace gl {

void RenderTarget::withRgba8(const std::function<void(const uint8_t* bottomUpRows)>& use) const {
  std::vector<uint8_t> rows(size_t(size_.x) * size_t(size_.y) * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_.get());
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, size_.x, size_.y, GL_RGBA, GL_UNSIGNED_BYTE, rows.data());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  use(rows.data());
}

}  // namespace gl

// Reading a render target through a pixel buffer: the driver copies into memory it owns and maps,
// where a read into the program's own memory waits on a copy into pages that fault on first touch.
#include "app/gl/gl.h"
#include "app/gl/texture.h"

#include <vector>

namespace gl {

void RenderTarget::withRgba8(const std::function<void(const uint8_t* bottomUpRows)>& use) const {
  const GLsizeiptr bytes = GLsizeiptr(size_.x) * size_.y * 4;
  GLuint buffer = 0;
  glGenBuffers(1, &buffer);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, buffer);
  glBufferData(GL_PIXEL_PACK_BUFFER, bytes, nullptr, GL_STREAM_READ);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_.get());
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, size_.x, size_.y, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  if (const void* pixels = glMapBufferRange(GL_PIXEL_PACK_BUFFER, 0, bytes, GL_MAP_READ_BIT)) {
    use(static_cast<const uint8_t*>(pixels));
    glUnmapBuffer(GL_PIXEL_PACK_BUFFER);
  } else {  // a driver that cannot map it: the plain read
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    std::vector<uint8_t> rows(static_cast<size_t>(bytes));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_.get());
    glReadPixels(0, 0, size_.x, size_.y, GL_RGBA, GL_UNSIGNED_BYTE, rows.data());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    use(rows.data());
  }
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  glDeleteBuffers(1, &buffer);
}

}  // namespace gl

// One RGBA float texel of a framebuffer, read back without a stall: copied into a pixel buffer and
// fenced, and taken a frame or two later once the GPU has got there (texel_read_desktop.cpp). A
// plain glReadPixels waits for everything drawn before it. The page reads it at once
// (texel_read_web.cpp): its WebGL2 waits for the GPU process on every read anyway, and
// emscripten hands out neither glGetBufferSubData nor a glClientWaitSync of the desktop's signature.
#pragma once
#include <array>
#include <optional>

#include "app/gl/handle.h"

namespace gl {

class TexelRead {
 public:
  TexelRead() = default;
  TexelRead(const TexelRead&) = delete;
  TexelRead& operator=(const TexelRead&) = delete;
  ~TexelRead();

  // Starts reading texel (x, y) (GL's order: from the bottom-left) of `fbo`'s first colour
  // attachment, unless a read is still in flight (then false).
  bool start(GLuint fbo, int x, int y);
  // The texel, once it has arrived (never waits); then the next start() may go.
  std::optional<std::array<float, 4>> take();
  bool inFlight() const { return inFlight_; }

 private:
  Buffer buffer_;
  GLsync fence_ = nullptr;
  bool inFlight_ = false;
  std::array<float, 4> texel_{};
};

}  // namespace gl

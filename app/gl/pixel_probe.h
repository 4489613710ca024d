// The viewport's pixel readout without a stall: the pixel under the cursor is read back a frame or
// two later, once the GPU has got there (gl::TexelRead). A plain glReadPixels waits for the whole
// frame to be drawn (in a browser, a round trip to its GPU process): a frame lost per frame while
// the cursor is over the viewport.
#pragma once
#include <array>
#include <optional>

#include "app/gl/texel_read.h"
#include "app/gl/texture.h"

namespace shadelab {

class PixelProbe {
 public:
  struct Value {
    int x = 0, y = 0;  // from the top-left, as images are
    std::array<float, 4> rgba{};
  };

  // Asks for pixel (x, y) of `target`'s colour; ignored while an earlier request is in flight or
  // outside the target.
  void request(const gl::RenderTarget& target, int x, int y);
  // Takes what has arrived (never waits); the last value that did.
  const std::optional<Value>& latest();

 private:
  gl::TexelRead read_;
  Value pending_;
  std::optional<Value> latest_;
};

}  // namespace shadelab

#include "app/gl/pixel_probe.h"

namespace shadelab {

void PixelProbe::request(const gl::RenderTarget& target, int x, int y) {
  if (x < 0 || y < 0 || x >= target.size().x || y >= target.size().y) return;
  if (read_.start(target.fbo(), x, target.size().y - 1 - y)) pending_ = {x, y, {}};
}

const std::optional<PixelProbe::Value>& PixelProbe::latest() {
  if (const auto texel = read_.take()) {
    pending_.rgba = *texel;
    latest_ = pending_;
  }
  return latest_;
}

}  // namespace shadelab

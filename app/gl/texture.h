// 2D textures and offscreen render targets.
#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include <glm/vec2.hpp>

#include "app/gl/handle.h"

namespace gl {

struct SamplerState {
  GLenum minFilter = GL_LINEAR_MIPMAP_LINEAR;
  GLenum magFilter = GL_LINEAR;
  GLenum wrapS = GL_REPEAT;
  GLenum wrapT = GL_REPEAT;
  float maxAnisotropy = 1.0f;  // 1 = isotropic; clamped to the driver's limit
};

// The driver's anisotropy limit (16 on llvmpipe), or 1 when it has no anisotropic filtering.
float maxAnisotropy();

// The pixel format and type to name when allocating `internalFormat` with no data: desktop GL takes
// any, OpenGL ES 3.0 and WebGL2 only the pairs of their format table (RGBA16F: RGBA, HALF_FLOAT;
// DEPTH_COMPONENT24: DEPTH_COMPONENT, UNSIGNED_INT; ...). Every allocation goes through this.
struct TransferFormat {
  GLenum format, type;
};
TransferFormat transferFormatFor(GLenum internalFormat);

class Texture2D {
 public:
  Texture2D() = default;
  // Immutable storage of `levels` mip levels (0 = full chain) in `internalFormat`.
  static Texture2D allocate(glm::ivec2 size, GLenum internalFormat, int levels = 1);
  // RGBA8 pixels, rows bottom-up as GL expects; builds mipmaps when the sampler asks for them.
  static Texture2D fromRgba8(glm::ivec2 size, const uint8_t* pixels, const SamplerState& sampler, bool srgb);
  // Any pixel layout (GL_R16 from GL_RED / GL_UNSIGNED_SHORT, ...), rows bottom-up, tightly packed.
  static Texture2D fromData(glm::ivec2 size, GLenum internalFormat, GLenum format, GLenum type, const void* pixels,
                            const SamplerState& sampler);
  // A mip chain made elsewhere, level 0 first, each level in `format` / `type` as fromData takes it;
  // the levels' sizes are max(1, size >> k), down to 1 x 1 for a complete chain.
  static Texture2D fromLevels(glm::ivec2 size, GLenum internalFormat, GLenum format, GLenum type,
                              const std::vector<const void*>& levels, const SamplerState& sampler);

  void setSampler(const SamplerState& s) const;
  void bind(int unit) const;
  GLuint id() const { return name_.get(); }
  glm::ivec2 size() const { return size_; }
  explicit operator bool() const { return bool(name_); }

 private:
  TextureName name_;
  glm::ivec2 size_{0};
  int levels_ = 1;
};

// Colour (float, so NaN and values above 1 survive for the stability scans) + depth.
class RenderTarget {
 public:
  static RenderTarget create(glm::ivec2 size, GLenum colorFormat = GL_RGBA16F);
  void bind() const;
  glm::ivec2 size() const { return size_; }
  const Texture2D& color() const { return color_; }
  GLuint fbo() const { return fbo_.get(); }
  // Reads the colour attachment as RGBA float, rows top-down (image order).
  std::vector<float> readRgba() const;
  // An 8-bit target's bytes (a quarter of the float read) handed to `use` where the driver puts
  // them, rows bottom-up as GL numbers them, valid during the call: no copy to flip them (read_back_desktop.cpp maps a
  // pixel buffer; WebGL2 cannot map one for reading, so the page reads into memory of its own).
  void withRgba8(const std::function<void(const uint8_t* bottomUpRows)>& use) const;
  // One pixel, (x, y) from the top-left as images are; all zero outside the target.
  std::array<float, 4> readPixel(int x, int y) const;

 private:
  FramebufferName fbo_;
  Texture2D color_;
  Renderbuffer depth_;
  glm::ivec2 size_{0};
};

}  // namespace gl

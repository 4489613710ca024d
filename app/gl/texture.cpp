#include "app/gl/texture.h"

#include "app/util/process_memory.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include <glm/glm.hpp>

namespace gl {

static int fullMipChain(glm::ivec2 s) { return 1 + int(std::floor(std::log2(std::max(1, std::max(s.x, s.y))))); }

float maxAnisotropy() {
  static const float limit = [] {
    GLint n = 0;
    glGetIntegerv(GL_NUM_EXTENSIONS, &n);
    bool present = false;
    for (GLint i = 0; i < n; ++i) {
      const char* e = reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, GLuint(i)));
      present |= e && (std::strcmp(e, "GL_EXT_texture_filter_anisotropic") == 0 ||
                       std::strcmp(e, "GL_ARB_texture_filter_anisotropic") == 0);
    }
    float value = 1.0f;
    if (present) glGetFloatv(GL_MAX_TEXTURE_MAX_ANISOTROPY, &value);
    return value;
  }();
  return limit;
}

TransferFormat transferFormatFor(GLenum internal) {
  switch (internal) {
    case GL_RGBA16F:
      return {GL_RGBA, GL_HALF_FLOAT};
    case GL_RGBA32F:
      return {GL_RGBA, GL_FLOAT};
    case GL_RGB16F:
      return {GL_RGB, GL_HALF_FLOAT};
    case GL_RGB32F:
      return {GL_RGB, GL_FLOAT};
    case GL_RG16F:
      return {GL_RG, GL_HALF_FLOAT};
    case GL_RG32F:
      return {GL_RG, GL_FLOAT};
    case GL_R16F:
      return {GL_RED, GL_HALF_FLOAT};
    case GL_R32F:
      return {GL_RED, GL_FLOAT};
    case GL_R8:
      return {GL_RED, GL_UNSIGNED_BYTE};
    case GL_R16:
      return {GL_RED, GL_UNSIGNED_SHORT};
    case GL_RG8:
      return {GL_RG, GL_UNSIGNED_BYTE};
    case GL_RGB8:
    case GL_SRGB8:
      return {GL_RGB, GL_UNSIGNED_BYTE};
    case GL_RGBA32I:
      return {GL_RGBA_INTEGER, GL_INT};
    case GL_RG32I:
      return {GL_RG_INTEGER, GL_INT};
    case GL_DEPTH_COMPONENT16:
      return {GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT};
    case GL_DEPTH_COMPONENT24:
      return {GL_DEPTH_COMPONENT, GL_UNSIGNED_INT};
    case GL_DEPTH_COMPONENT32F:
      return {GL_DEPTH_COMPONENT, GL_FLOAT};
    case GL_DEPTH24_STENCIL8:
      return {GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8};
    case GL_DEPTH32F_STENCIL8:
      return {GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV};
    default:
      return {GL_RGBA, GL_UNSIGNED_BYTE};  // RGBA8, SRGB8_ALPHA8
  }
}

Texture2D Texture2D::allocate(glm::ivec2 size, GLenum internalFormat, int levels) {
  Texture2D t;
  t.name_ = TextureName::make();
  t.size_ = size;
  t.levels_ = levels > 0 ? levels : fullMipChain(size);
  glBindTexture(GL_TEXTURE_2D, t.id());
  // Every level, as GL 3.3 allocates them (glTexStorage2D is 4.2); MAX_LEVEL marks the chain complete.
  const TransferFormat transfer = transferFormatFor(internalFormat);
  for (int level = 0; level < t.levels_; ++level) {
    const glm::ivec2 s = glm::max(size >> level, glm::ivec2(1));
    glTexImage2D(GL_TEXTURE_2D, level, GLint(internalFormat), s.x, s.y, 0, transfer.format, transfer.type, nullptr);
  }
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, t.levels_ - 1);
  SamplerState s;
  s.minFilter = t.levels_ > 1 ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR;
  s.wrapS = s.wrapT = GL_CLAMP_TO_EDGE;
  t.setSampler(s);
  return t;
}

Texture2D Texture2D::fromRgba8(glm::ivec2 size, const uint8_t* pixels, const SamplerState& sampler, bool srgb) {
  const bool mips = sampler.minFilter != GL_LINEAR && sampler.minFilter != GL_NEAREST;
  Texture2D t = allocate(size, srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8, mips ? 0 : 1);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, size.x, size.y, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
  if (mips) glGenerateMipmap(GL_TEXTURE_2D);
  t.setSampler(sampler);
  return t;
}

Texture2D Texture2D::fromData(glm::ivec2 size, GLenum internalFormat, GLenum format, GLenum type, const void* pixels,
                              const SamplerState& sampler) {
  const bool mips = sampler.minFilter != GL_LINEAR && sampler.minFilter != GL_NEAREST;
  Texture2D t = allocate(size, internalFormat, mips ? 0 : 1);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, size.x, size.y, format, type, pixels);
  if (mips) glGenerateMipmap(GL_TEXTURE_2D);
  t.setSampler(sampler);
  return t;
}

Texture2D Texture2D::fromLevels(glm::ivec2 size, GLenum internalFormat, GLenum format, GLenum type,
                                const std::vector<const void*>& levels, const SamplerState& sampler) {
  Texture2D t = allocate(size, internalFormat, std::max(int(levels.size()), 1));
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  for (size_t level = 0; level < levels.size(); ++level) {
    const glm::ivec2 s = glm::max(size >> int(level), glm::ivec2(1));
    glTexSubImage2D(GL_TEXTURE_2D, GLint(level), 0, 0, s.x, s.y, format, type, levels[level]);
  }
  t.setSampler(sampler);
  return t;
}

void Texture2D::setSampler(const SamplerState& s) const {
  glBindTexture(GL_TEXTURE_2D, id());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, s.minFilter);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, s.magFilter);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, s.wrapS);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, s.wrapT);
  // Always set (1 turns it off again), where the driver has anisotropic filtering at all.
  if (maxAnisotropy() > 1.0f)
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY, std::clamp(s.maxAnisotropy, 1.0f, maxAnisotropy()));
}

void Texture2D::bind(int unit) const {
  glActiveTexture(GL_TEXTURE0 + unit);
  glBindTexture(GL_TEXTURE_2D, id());
}

RenderTarget RenderTarget::create(glm::ivec2 size, GLenum colorFormat) {
  RenderTarget rt;
  rt.size_ = size;
  rt.color_ = Texture2D::allocate(size, colorFormat, 1);
  // A frame is shown and read pixel for pixel: a nearest lookup is the same picture for less work
  // (the window draws it every frame; llvmpipe's bilinear fetch of a half-float texture is not free).
  SamplerState nearest;
  nearest.minFilter = nearest.magFilter = GL_NEAREST;
  nearest.wrapS = nearest.wrapT = GL_CLAMP_TO_EDGE;
  rt.color_.setSampler(nearest);
  rt.depth_ = Renderbuffer::make();
  glBindRenderbuffer(GL_RENDERBUFFER, rt.depth_.get());
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, size.x, size.y);
  rt.fbo_ = FramebufferName::make();
  glBindFramebuffer(GL_FRAMEBUFFER, rt.fbo_.get());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, rt.color_.id(), 0);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, rt.depth_.get());
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    char why[160];
    std::snprintf(why, sizeof why,
                  "render target %dx%d could not be allocated (framebuffer status 0x%04X, %s): pick a smaller size",
                  size.x, size.y, unsigned(status), gl::drainErrors().empty() ? "no GL error" : "out of memory");
    throw std::runtime_error(why);
  }
  return rt;
}

void RenderTarget::bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.get());
  glViewport(0, 0, size_.x, size_.y);
}

std::vector<float> RenderTarget::readRgba() const {
  std::vector<float> rows = shadelab::largeBuffer<float>(size_t(size_.x) * size_t(size_.y) * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_.get());
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, size_.x, size_.y, GL_RGBA, GL_FLOAT, rows.data());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  // Top row first, flipped in place (a second image-sized buffer costs as much as the read).
  const size_t stride = size_t(size_.x) * 4;
  for (int y = 0; y < size_.y / 2; ++y)
    std::swap_ranges(rows.begin() + y * stride, rows.begin() + (y + 1) * stride,
                     rows.begin() + (size_.y - 1 - y) * stride);
  return rows;
}

std::array<float, 4> RenderTarget::readPixel(int x, int y) const {
  std::array<float, 4> px{};
  if (x < 0 || y < 0 || x >= size_.x || y >= size_.y) return px;
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_.get());
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glReadPixels(x, size_.y - 1 - y, 1, 1, GL_RGBA, GL_FLOAT, px.data());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  return px;
}

}  // namespace gl

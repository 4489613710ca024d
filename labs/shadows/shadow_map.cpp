#include "labs/shadows/shadow_map.h"

#include <algorithm>
#include <string>

namespace shadelab {
namespace {

int mipLevels(int size) {
  int levels = 1;
  while ((size >> levels) > 0) ++levels;
  return levels;
}

// The whole cube as a layered attachment for the geometry shader's single pass; where there are no
// geometry shaders (ES 3.0, WebGL2) its first face, and the six passes attach each face in turn.
void attachCube(GLuint texture) {
  if (glFramebufferTexture)
    glFramebufferTexture(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, texture, 0);
  else
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_CUBE_MAP_POSITIVE_X, texture, 0);
}

void allocateArray(GLuint texture, GLenum internal, int size, int layers, int levels) {
  glBindTexture(GL_TEXTURE_2D_ARRAY, texture);
  const gl::TransferFormat transfer = gl::transferFormatFor(internal);
  for (int level = 0; level < levels; ++level) {
    const int s = std::max(size >> level, 1);
    glTexImage3D(GL_TEXTURE_2D_ARRAY, level, GLint(internal), s, s, layers, 0, transfer.format, transfer.type, nullptr);
  }
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAX_LEVEL, levels - 1);
  // The texture's own filtering serves reads with no sampler object (the blur's texelFetch, the
  // dummies); lookups in lit.frag go through the samplers, which override it.
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
}

// Whether the framebuffer bound now is complete and nothing before it ran out of memory.
bool complete() {
  const bool outOfMemory = !gl::drainErrors().empty();
  return !outOfMemory && glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
}

}  // namespace

double ShadowMap::bytesOf(const MapShape& shape) {
  const double texels = double(shape.size) * shape.size * (shape.cube ? 6 : shape.layers);
  const double moments = shape.momentFormat == GL_R32F    ? 4
                         : shape.momentFormat == GL_RG32F ? 8
                         : shape.momentFormat             ? 16
                                                          : 0;
  const double scratch = shape.cube ? 0.0 : double(shape.size) * shape.size * moments;  // one blur layer
  return texels * (4.0 + moments * (shape.momentMips ? 4.0 / 3.0 : 1.0)) + scratch;
}

int ShadowMap::ensure(const MapShape& shape, double budgetBytes) {
  if (texture_ && shape == requested_ && budgetBytes == requestedBudget_) return shape_.size;
  release();
  requested_ = shape;
  requestedBudget_ = budgetBytes;
  gl::drainErrors();  // errors from before are not this allocation's
  for (MapShape attempt = shape; attempt.size >= 256; attempt.size /= 2) {
    if (bytesOf(attempt) > budgetBytes && attempt.size > 256) continue;
    if (allocate(attempt)) return attempt.size;
    release();
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return 0;
}

bool ShadowMap::allocate(const MapShape& shape) {
  shape_ = shape;
  const int size = shape.size;
  texture_ = gl::TextureName::make();
  if (shape.cube) {
    glBindTexture(GL_TEXTURE_CUBE_MAP, texture_.get());
    const gl::TransferFormat transfer = gl::transferFormatFor(shape.depthFormat);
    for (int f = 0; f < 6; ++f)
      glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, 0, GLint(shape.depthFormat), size, size, 0, transfer.format,
                   transfer.type, nullptr);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAX_LEVEL, 0);
  } else {
    allocateArray(texture_.get(), shape.depthFormat, size, shape.layers, 1);
  }
  if (shape.cube) {  // layered: the geometry shader picks the face (or six passes attach one each)
    fbo_ = gl::FramebufferName::make();
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.get());
    attachCube(texture_.get());
    const GLenum none = GL_NONE;
    glDrawBuffers(1, &none);
    glReadBuffer(GL_NONE);
    if (!complete()) return false;
  }
  if (shape.momentFormat && !shape.cube) {
    moments_ = gl::TextureName::make();
    allocateArray(moments_.get(), shape.momentFormat, size, shape.layers, shape.momentMips ? mipLevels(size) : 1);
    blurTemp_ = gl::TextureName::make();
    allocateArray(blurTemp_.get(), shape.momentFormat, size, 1, 1);
    blurFbo_ = gl::FramebufferName::make();
    glBindFramebuffer(GL_FRAMEBUFFER, blurFbo_.get());
    glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, blurTemp_.get(), 0, 0);
    const GLenum color = GL_COLOR_ATTACHMENT0;
    glDrawBuffers(1, &color);
    if (!complete()) return false;
    momentSampler_ = gl::Sampler::make();
    glSamplerParameteri(momentSampler_.get(), GL_TEXTURE_MIN_FILTER,
                        shape.momentMips ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR);
    glSamplerParameteri(momentSampler_.get(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glSamplerParameteri(momentSampler_.get(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(momentSampler_.get(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  }
  if (!shape.cube)
    for (int layer = 0; layer < shape.layers; ++layer) {
      layerFbos_.push_back(gl::FramebufferName::make());
      glBindFramebuffer(GL_FRAMEBUFFER, layerFbos_.back().get());
      glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, texture_.get(), 0, layer);
      if (moments_) glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, moments_.get(), 0, layer);
      const GLenum draw = moments_ ? GL_COLOR_ATTACHMENT0 : GL_NONE;
      glDrawBuffers(1, &draw);
      glReadBuffer(GL_NONE);
      if (!complete()) return false;
    }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);

  raw_ = gl::Sampler::make();
  compare_ = gl::Sampler::make();
  glSamplerParameteri(raw_.get(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glSamplerParameteri(raw_.get(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glSamplerParameteri(compare_.get(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glSamplerParameteri(compare_.get(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glSamplerParameteri(compare_.get(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glSamplerParameteri(compare_.get(), GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  if (gl::hasBorderColor()) {
    const float border[4] = {1.0f, 1.0f, 1.0f, 1.0f};
    for (GLuint s : {raw_.get(), compare_.get()}) glSamplerParameterfv(s, GL_TEXTURE_BORDER_COLOR, border);
  }
  return true;
}

void ShadowMap::render(const Scene& scene, const GpuScene& gpu, Program& program, const LightFrame& light, int layer,
                       const DepthPassState& state) {
  const int size = shape_.size;
  glBindFramebuffer(GL_FRAMEBUFFER, shape_.cube ? fbo_.get() : layerFbos_[size_t(layer)].get());
  glViewport(0, 0, size, size);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  if (moments_) {
    // Where nothing was drawn the moments are those of the far plane: lit.
    glClearColor(state.momentClear.r, state.momentClear.g, state.momentClear.b, state.momentClear.a);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  } else {
    glClear(GL_DEPTH_BUFFER_BIT);
  }
  if (state.cullFront) {
    glEnable(GL_CULL_FACE);
    glCullFace(GL_FRONT);
  }
  const bool offset = state.offsetFactor != 0.0f || state.offsetUnits != 0.0f;
  if (offset) {
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(state.offsetFactor, state.offsetUnits);
  }
  program.use();
  auto drawAll = [&] {
    for (const Instance& inst : scene.instances) {
      program.set("u_model", inst.model);
      gpu.draw(inst);
    }
  };
  if (shape_.cube) {
    program.set("u_lightPos", light.position);
    program.set("u_far", light.farPlane);
  }
  if (moments_) {
    program.set("u_lightPos", light.position);
    program.set("u_lightAxis", light.direction);
    program.set("u_near", light.nearPlane);
    program.set("u_far", light.farPlane);
  }
  if (shape_.cube && state.sixPasses) {
    for (int f = 0; f < 6; ++f) {  // one face at a time: the vertices are submitted six times
      glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, texture_.get(),
                             0);
      glClear(GL_DEPTH_BUFFER_BIT);
      program.set("u_lightViewProj", light.faceViewProj[f]);
      drawAll();
    }
    attachCube(texture_.get());  // layered again
  } else if (shape_.cube) {
    program.setArray("u_faceViewProj", light.faceViewProj, 6);
    drawAll();
  } else {
    program.set("u_lightViewProj", light.viewProj);
    drawAll();
  }
  if (offset) glDisable(GL_POLYGON_OFFSET_FILL);
  if (state.cullFront) {
    glCullFace(GL_BACK);
    glDisable(GL_CULL_FACE);
  }
}

void ShadowMap::filterMoments(Program& blur, int radius, GLuint emptyVao) {
  if (!moments_) return;
  const int size = shape_.size;
  if (radius > 0) {
    glDisable(GL_DEPTH_TEST);  // each layer's framebuffer has its depth layer attached: no test against it
    glViewport(0, 0, size, size);
    blur.use();
    blur.set("u_src", 0);
    blur.set("u_radius", radius);
    glActiveTexture(GL_TEXTURE0);
    glBindSampler(0, 0);
    glBindVertexArray(emptyVao);
    for (int layer = 0; layer < shape_.layers; ++layer) {
      // Across: this layer of the moments -> the scratch layer; down: back into this layer.
      glBindFramebuffer(GL_FRAMEBUFFER, blurFbo_.get());
      glBindTexture(GL_TEXTURE_2D_ARRAY, moments_.get());
      blur.set("u_layer", layer);
      blur.set("u_direction", glm::vec2(1.0f, 0.0f));
      glDrawArrays(GL_TRIANGLES, 0, 3);
      glBindFramebuffer(GL_FRAMEBUFFER, layerFbos_[size_t(layer)].get());
      glBindTexture(GL_TEXTURE_2D_ARRAY, blurTemp_.get());
      blur.set("u_layer", 0);
      blur.set("u_direction", glm::vec2(0.0f, 1.0f));
      glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    glEnable(GL_DEPTH_TEST);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (shape_.momentMips) {
    glBindTexture(GL_TEXTURE_2D_ARRAY, moments_.get());
    glGenerateMipmap(GL_TEXTURE_2D_ARRAY);
  }
}

void ShadowMap::bind(int rawUnit, int compareUnit, bool border) {
  const GLenum target = shape_.cube ? GL_TEXTURE_CUBE_MAP : GL_TEXTURE_2D_ARRAY;
  if (wrapBorder_ != int(border)) {  // sampler state changes make drivers revalidate: only on change
    const GLint wrap = border && gl::hasBorderColor() ? GL_CLAMP_TO_BORDER : GL_CLAMP_TO_EDGE;
    for (GLuint s : {raw_.get(), compare_.get()}) {
      glSamplerParameteri(s, GL_TEXTURE_WRAP_S, wrap);
      glSamplerParameteri(s, GL_TEXTURE_WRAP_T, wrap);
      glSamplerParameteri(s, GL_TEXTURE_WRAP_R, wrap);
    }
    wrapBorder_ = int(border);
  }
  glActiveTexture(GL_TEXTURE0 + rawUnit);
  glBindTexture(target, texture_.get());
  glBindSampler(rawUnit, raw_.get());
  glActiveTexture(GL_TEXTURE0 + compareUnit);
  glBindTexture(target, texture_.get());
  glBindSampler(compareUnit, compare_.get());
}

void ShadowMap::bindMoments(int unit) const {
  glActiveTexture(GL_TEXTURE0 + unit);
  glBindTexture(GL_TEXTURE_2D_ARRAY, moments_.get());
  glBindSampler(unit, momentSampler_.get());
}

void ShadowMap::release() {
  fbo_.reset();
  layerFbos_.clear();
  wrapBorder_ = -1;
  blurFbo_.reset();
  texture_.reset();
  moments_.reset();
  blurTemp_.reset();
  raw_.reset();
  compare_.reset();
  momentSampler_.reset();
  shape_ = {};
}

void DummyDepthTextures::create() {
  array_ = gl::TextureName::make();
  allocateArray(array_.get(), GL_DEPTH_COMPONENT16, 1, 1, 1);
  cube_ = gl::TextureName::make();
  glBindTexture(GL_TEXTURE_CUBE_MAP, cube_.get());
  for (int f = 0; f < 6; ++f)
    glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, 0, GL_DEPTH_COMPONENT16, 1, 1, 0, GL_DEPTH_COMPONENT,
                 GL_UNSIGNED_SHORT, nullptr);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAX_LEVEL, 0);
  moments_ = gl::TextureName::make();
  allocateArray(moments_.get(), GL_RGBA32F, 1, 1, 1);
  raw_ = gl::Sampler::make();
  compare_ = gl::Sampler::make();
  for (GLuint s : {raw_.get(), compare_.get()}) {
    glSamplerParameteri(s, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glSamplerParameteri(s, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  }
  glSamplerParameteri(compare_.get(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
}

void DummyDepthTextures::bindArray(int unit, bool compare) const {
  glActiveTexture(GL_TEXTURE0 + unit);
  glBindTexture(GL_TEXTURE_2D_ARRAY, array_.get());
  glBindSampler(unit, compare ? compare_.get() : raw_.get());
}

void DummyDepthTextures::bindCube(int unit, bool compare) const {
  glActiveTexture(GL_TEXTURE0 + unit);
  glBindTexture(GL_TEXTURE_CUBE_MAP, cube_.get());
  glBindSampler(unit, compare ? compare_.get() : raw_.get());
}

void DummyDepthTextures::bindMoments(int unit) const {
  glActiveTexture(GL_TEXTURE0 + unit);
  glBindTexture(GL_TEXTURE_2D_ARRAY, moments_.get());
  glBindSampler(unit, 0);
}

void DummyDepthTextures::release() {
  array_.reset();
  cube_.reset();
  moments_.reset();
  raw_.reset();
  compare_.reset();
}

}  // namespace shadelab

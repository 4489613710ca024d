#include "labs/shadows/shadow_map.h"

#include <stdexcept>
#include <string>

namespace shadelab {

void ShadowMap::ensure(bool cube, int size, GLenum format) {
  if (texture_ && cube == cube_ && size == size_ && format == format_) return;
  release();
  cube_ = cube;
  size_ = size;
  format_ = format;
  texture_ = gl::TextureName::make();
  const GLenum target = cube ? GL_TEXTURE_CUBE_MAP : GL_TEXTURE_2D;
  glBindTexture(target, texture_.get());
  glTexStorage2D(target, 1, format, size, size);
  fbo_ = gl::FramebufferName::make();
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.get());
  glFramebufferTexture(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, texture_.get(), 0);  // all six faces if a cube
  glDrawBuffer(GL_NONE);
  glReadBuffer(GL_NONE);
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (status != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error("shadow map " + std::to_string(size) + "^2 is incomplete (status " + std::to_string(status) + ")");

  raw_ = gl::Sampler::make();
  compare_ = gl::Sampler::make();
  glSamplerParameteri(raw_.get(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glSamplerParameteri(raw_.get(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glSamplerParameteri(compare_.get(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glSamplerParameteri(compare_.get(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glSamplerParameteri(compare_.get(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glSamplerParameteri(compare_.get(), GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  const float border[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  for (GLuint s : {raw_.get(), compare_.get()}) glSamplerParameterfv(s, GL_TEXTURE_BORDER_COLOR, border);
}

void ShadowMap::render(const Scene& scene, const GpuScene& gpu, Program& program, const LightFrame& light,
                       const DepthPassState& state) {
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.get());
  glViewport(0, 0, size_, size_);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glClear(GL_DEPTH_BUFFER_BIT);
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
  if (cube_) {
    program.set("u_lightPos", light.position);
    program.set("u_far", light.farPlane);
  }
  if (cube_ && state.sixPasses) {
    for (int f = 0; f < 6; ++f) {  // one face at a time: the vertices are submitted six times
      glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, texture_.get(), 0, f);
      glClear(GL_DEPTH_BUFFER_BIT);
      program.set("u_lightViewProj", light.faceViewProj[f]);
      drawAll();
    }
    glFramebufferTexture(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, texture_.get(), 0);  // layered again
  } else if (cube_) {
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

void ShadowMap::bind(int rawUnit, int compareUnit, bool border) const {
  const GLenum target = cube_ ? GL_TEXTURE_CUBE_MAP : GL_TEXTURE_2D;
  const GLint wrap = border ? GL_CLAMP_TO_BORDER : GL_CLAMP_TO_EDGE;
  for (GLuint s : {raw_.get(), compare_.get()}) {
    glSamplerParameteri(s, GL_TEXTURE_WRAP_S, wrap);
    glSamplerParameteri(s, GL_TEXTURE_WRAP_T, wrap);
    glSamplerParameteri(s, GL_TEXTURE_WRAP_R, wrap);
  }
  glActiveTexture(GL_TEXTURE0 + rawUnit);
  glBindTexture(target, texture_.get());
  glBindSampler(rawUnit, raw_.get());
  glActiveTexture(GL_TEXTURE0 + compareUnit);
  glBindTexture(target, texture_.get());
  glBindSampler(compareUnit, compare_.get());
}

void ShadowMap::release() {
  fbo_.reset();
  texture_.reset();
  raw_.reset();
  compare_.reset();
  size_ = 0;
}

void DummyDepthTextures::create() {
  tex2D_ = gl::TextureName::make();
  glBindTexture(GL_TEXTURE_2D, tex2D_.get());
  glTexStorage2D(GL_TEXTURE_2D, 1, GL_DEPTH_COMPONENT16, 1, 1);
  texCube_ = gl::TextureName::make();
  glBindTexture(GL_TEXTURE_CUBE_MAP, texCube_.get());
  glTexStorage2D(GL_TEXTURE_CUBE_MAP, 1, GL_DEPTH_COMPONENT16, 1, 1);
}

void DummyDepthTextures::bind2D(int unit) const {
  glActiveTexture(GL_TEXTURE0 + unit);
  glBindTexture(GL_TEXTURE_2D, tex2D_.get());
  glBindSampler(unit, 0);
}

void DummyDepthTextures::bindCube(int unit) const {
  glActiveTexture(GL_TEXTURE0 + unit);
  glBindTexture(GL_TEXTURE_CUBE_MAP, texCube_.get());
  glBindSampler(unit, 0);
}

void DummyDepthTextures::release() {
  tex2D_.reset();
  texCube_.reset();
}

}  // namespace shadelab

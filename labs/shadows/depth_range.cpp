#include "labs/shadows/depth_range.h"

namespace shadelab {

ProgramSpec DepthRange::programSpec(bool fromDepth) {
  ProgramSpec spec;
  spec.name = fromDepth ? "shadows/depth range (camera depth)" : "shadows/depth range";
  spec.stages = {{GL_VERTEX_SHADER, "common/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "shadows/depth_range.frag"}};
  if (fromDepth) spec.defines.emplace_back("FROM_DEPTH", "1");
  return spec;
}

void DepthRange::allocate(glm::ivec2 size) {
  size_ = size;
  // A depth texture of the camera target's own format: the depth buffer is blitted into it.
  depth_ = gl::TextureName::make();
  glBindTexture(GL_TEXTURE_2D, depth_.get());
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH24_STENCIL8, size.x, size.y, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8,
               nullptr);
  for (GLenum p : {GL_TEXTURE_MIN_FILTER, GL_TEXTURE_MAG_FILTER}) glTexParameteri(GL_TEXTURE_2D, p, GL_NEAREST);
  depthFbo_ = gl::FramebufferName::make();
  glBindFramebuffer(GL_FRAMEBUFFER, depthFbo_.get());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_TEXTURE_2D, depth_.get(), 0);
  levels_.clear();
  for (glm::ivec2 s = size; s != glm::ivec2(1);) {
    s = glm::max((s + 7) / 8, glm::ivec2(1));
    Level level;
    level.size = s;
    level.texture = gl::TextureName::make();
    glBindTexture(GL_TEXTURE_2D, level.texture.get());
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RG32F, s.x, s.y, 0, GL_RG, GL_FLOAT, nullptr);
    for (GLenum p : {GL_TEXTURE_MIN_FILTER, GL_TEXTURE_MAG_FILTER}) glTexParameteri(GL_TEXTURE_2D, p, GL_NEAREST);
    level.fbo = gl::FramebufferName::make();
    glBindFramebuffer(GL_FRAMEBUFFER, level.fbo.get());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, level.texture.get(), 0);
    levels_.push_back(std::move(level));
  }
  glBindTexture(GL_TEXTURE_2D, 0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void DepthRange::reduce(const gl::RenderTarget& target, const glm::mat4& viewProj, glm::vec2 planes, Program& first,
                        Program& rest, GLuint emptyVao) {
  rangeFor(viewProj);  // a read that has arrived is taken first
  if (target.size() != size_ || !depth_) allocate(target.size());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, target.fbo());
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, depthFbo_.get());
  glBlitFramebuffer(0, 0, size_.x, size_.y, 0, 0, size_.x, size_.y, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glBindVertexArray(emptyVao);
  glActiveTexture(GL_TEXTURE0);
  glBindSampler(0, 0);
  glm::ivec2 source = size_;
  for (size_t i = 0; i < levels_.size(); ++i) {
    Program& prog = i == 0 ? first : rest;
    prog.use();
    prog.set("u_size", glm::vec2(source));
    if (i == 0) {
      prog.set("u_depth", 0);
      prog.set("u_planes", planes);
      glBindTexture(GL_TEXTURE_2D, depth_.get());
    } else {
      prog.set("u_level", 0);
      glBindTexture(GL_TEXTURE_2D, levels_[i - 1].texture.get());
    }
    glBindFramebuffer(GL_FRAMEBUFFER, levels_[i].fbo.get());
    glViewport(0, 0, levels_[i].size.x, levels_[i].size.y);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    source = levels_[i].size;
  }
  glBindTexture(GL_TEXTURE_2D, 0);
  glEnable(GL_DEPTH_TEST);
  // The 1x1 result on its way back: the next frame takes it. One still in flight (the GPU is
  // behind) keeps its place, and this frame's is not read.
  if (read_.start(levels_.back().fbo.get(), 0, 0)) pendingViewProj_ = viewProj;
  target.bind();
}

std::optional<glm::vec2> DepthRange::rangeFor(const glm::mat4& viewProj) {
  if (const auto r = read_.take()) {
    viewProj_ = pendingViewProj_;
    // (1e30, -1e30): the camera drew nothing; a NaN (a broken depth buffer) is no range either.
    range_ = (*r)[0] <= (*r)[1] ? std::optional<glm::vec2>(glm::vec2((*r)[0], (*r)[1])) : std::nullopt;
  }
  if (!range_ || viewProj_ != viewProj) return std::nullopt;
  return range_;
}

void DepthRange::release() {
  depth_ = gl::TextureName();
  depthFbo_ = gl::FramebufferName();
  levels_.clear();
  size_ = glm::ivec2(0);
  range_.reset();  // (a read still in flight is taken and dropped by the camera check)
}

}  // namespace shadelab

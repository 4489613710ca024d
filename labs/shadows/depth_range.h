// The depth-range fit (sample distribution shadow maps, Lauritzen, Salvi and Lefohn 2011): the
// nearest and farthest view depth the camera actually drew, reduced on the GPU from its depth
// buffer, for the cascades of the next frame. What the camera could see (its frustum clipped to
// the scene's boxes) bounds what it does see; behind a wall, or with the far floor out of the
// picture, the drawn range is much shorter, and the cascades' texels go where the pixels are.
//
// The reduction is read back a frame late (gl::TexelRead): the frame that fits its maps never
// waits for its own depth. A range is used only by a frame from the same camera as the one
// that drew it (a moving camera's frames fall back to the frustum's range until it stops).
#pragma once
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "app/gl/handle.h"
#include "app/gl/texel_read.h"
#include "app/gl/texture.h"
#include "app/shader/shader_library.h"

namespace shadelab {

class DepthRange {
 public:
  // The programs it draws with: the first pass reads the camera's depth (FROM_DEPTH), the others
  // reduce the pass before, 8x8 texels into one each.
  static ProgramSpec programSpec(bool fromDepth);

  // Reduces `target`'s depth buffer, drawn with `viewProj` and the camera's near and far planes, to
  // (nearest, farthest) view depth, and starts reading it back. `first` and `rest` are
  // programSpec(true) and programSpec(false).
  void reduce(const gl::RenderTarget& target, const glm::mat4& viewProj, glm::vec2 planes, Program& first,
              Program& rest, GLuint emptyVao);
  // The range the last reduce() found, if it was drawn from `viewProj` and held any surface.
  std::optional<glm::vec2> rangeFor(const glm::mat4& viewProj);
  // The textures go; the next reduce() makes them again.
  void release();

 private:
  struct Level {
    gl::TextureName texture;
    gl::FramebufferName fbo;
    glm::ivec2 size{0};
  };
  glm::ivec2 size_{0};  // the camera target's size the levels were made for
  gl::TextureName depth_;
  gl::FramebufferName depthFbo_;
  std::vector<Level> levels_;  // down to 1x1
  gl::TexelRead read_;         // the 1x1 level's texel, on its way back
  glm::mat4 pendingViewProj_{0.0f}, viewProj_{0.0f};
  std::optional<glm::vec2> range_;
  void allocate(glm::ivec2 size);
};

}  // namespace shadelab

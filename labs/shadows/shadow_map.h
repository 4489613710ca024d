// A light's depth map on the GPU (a 2D texture, or a cube for a point light), the framebuffer the
// depth pass draws into, and two samplers over the same texture: one reads raw depth (for PCF
// taps and the PCSS blocker search), one compares in hardware (sampler2DShadow).
#pragma once
#include "gl/texture.h"
#include "labs/shadows/light_rig.h"
#include "scene/gpu_scene.h"
#include "shader/shader_library.h"

namespace shadelab {

struct DepthPassState {
  bool cullFront = false;      // draw back faces only: the stored surface moves off lit fronts
  float offsetFactor = 0.0f;   // glPolygonOffset(factor, units); 0, 0 = off
  float offsetUnits = 0.0f;
  bool sixPasses = false;      // cube maps: one pass per face instead of one geometry-shader pass
};

class ShadowMap {
 public:
  // (Re)allocates only when the shape, size or format changes.
  void ensure(bool cube, int size, GLenum depthFormat);
  // Draws every instance's depth from the light. `program` is the depth program variant for
  // this map (CUBE_MAP for a one-pass cube, CUBE_FACE for six passes).
  void render(const Scene& scene, const GpuScene& gpu, Program& program, const LightFrame& light,
              const DepthPassState& state);
  // Binds the raw sampler to `rawUnit` and the comparing one to `compareUnit`; `border` picks
  // CLAMP_TO_BORDER (depth 1: outside the map is lit) over CLAMP_TO_EDGE (edge texels repeat).
  void bind(int rawUnit, int compareUnit, bool border) const;
  void release();

  bool cube() const { return cube_; }
  int size() const { return size_; }
  explicit operator bool() const { return bool(texture_); }

 private:
  gl::TextureName texture_;
  gl::FramebufferName fbo_;
  gl::Sampler raw_, compare_;
  bool cube_ = false;
  int size_ = 0;
  GLenum format_ = 0;
};

// 1x1 depth textures, 2D and cube, bound to sampler units a configuration does not use: GL
// forbids samplers of different types on one unit, so every unit gets a texture of its type.
class DummyDepthTextures {
 public:
  void create();
  void bind2D(int unit) const;
  void bindCube(int unit) const;
  void release();

 private:
  gl::TextureName tex2D_, texCube_;
};

}  // namespace shadelab

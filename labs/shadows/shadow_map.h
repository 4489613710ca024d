// A light's depth map on the GPU: a 2D array (one layer per cascade; one layer for a spot or an
// unsplit directional light) or a cube for a point light, the framebuffer the depth pass draws
// into, and two samplers over the same texture: one reads raw depth (PCF taps, the PCSS blocker
// search), one compares in hardware (sampler2DArrayShadow). Filtered maps (VSM, ESM, EVSM) add a
// float colour array of moments, written by the same pass, blurred and mipmapped.
#pragma once
#include <vector>

#include "app/gl/texture.h"
#include "app/scene/gpu_scene.h"
#include "app/shader/shader_library.h"
#include "labs/shadows/light_rig.h"

namespace shadelab {

struct DepthPassState {
  bool cullFront = false;     // draw back faces only: the stored surface moves off lit fronts
  float offsetFactor = 0.0f;  // glPolygonOffset(factor, units); 0, 0 = off
  float offsetUnits = 0.0f;
  bool sixPasses = false;       // cube maps: one pass per face instead of one geometry-shader pass
  glm::vec4 momentClear{1.0f};  // filtered maps: the moments of the far plane (where nothing is drawn)
};

struct MapShape {
  bool cube = false;
  int size = 0;
  int layers = 1;  // 2D arrays: cascades
  GLenum depthFormat = 0;
  GLenum momentFormat = 0;  // 0: no moments; GL_R32F (ESM), GL_RG32F (VSM), GL_RGBA32F (EVSM)
  bool momentMips = false;
  bool operator==(const MapShape&) const = default;
};

class ShadowMap {
 public:
  // (Re)allocates only when the shape or the budget changes. Where the shape needs more than
  // `budgetBytes` (an 8192^2 cube or four cascades of RGBA32F moments are gigabytes: a software
  // renderer takes them from the machine's memory, which a laptop may not have) or the driver
  // cannot allocate it, halves the size until it fits and returns the size it got: shape.size, a
  // smaller one, or 0 (not even 256^2; no map then). The lab's maps share kBudgetBytes.
  int ensure(const MapShape& shape, double budgetBytes);
  static constexpr double kBudgetBytes = 2.0 * 1024 * 1024 * 1024;
  double bytes() const { return texture_ ? bytesOf(shape_) : 0.0; }  // what the map holds now
  // Draws every instance's depth (and moments) from `light` into `layer`. `program` is the depth
  // program variant for this map (CUBE_MAP for a one-pass cube, CUBE_FACE for six passes,
  // MOMENTS for a filtered map).
  void render(const Scene& scene, const GpuScene& gpu, Program& program, const LightFrame& light, int layer,
              const DepthPassState& state);
  // Separable Gaussian blur of every moment layer, `radius` texels each way (0: none), then the
  // mip chain when the shape asks for one. `blur` is shaders/shadows/blur.frag; `emptyVao` draws
  // its full-screen triangle.
  void filterMoments(Program& blur, int radius, GLuint emptyVao);
  // Binds the raw sampler to `rawUnit` and the comparing one to `compareUnit`; `border` picks
  // CLAMP_TO_BORDER (depth 1: outside the map is lit) over CLAMP_TO_EDGE (edge texels repeat).
  void bind(int rawUnit, int compareUnit, bool border);
  void bindMoments(int unit) const;  // trilinear (the shader picks the level per pixel)
  void release();

  bool cube() const { return shape_.cube; }
  int size() const { return shape_.size; }
  int layers() const { return shape_.layers; }
  bool hasMoments() const { return bool(moments_); }
  GLuint texture() const { return texture_.get(); }
  explicit operator bool() const { return bool(texture_); }
  // What `shape` needs in GPU memory, bytes: depth, moments with their mips and the blur's scratch.
  static double bytesOf(const MapShape& shape);

 private:
  gl::TextureName texture_, moments_, blurTemp_;
  gl::FramebufferName fbo_, blurFbo_;
  std::vector<gl::FramebufferName> layerFbos_;  // 2D arrays: one per layer, attached once (re-attaching
                                                // every frame makes drivers revalidate the framebuffer)
  gl::Sampler raw_, compare_, momentSampler_;
  bool allocate(const MapShape& shape);  // false (and a GL error drained) when the driver refuses
  MapShape requested_;                   // what ensure() was last asked for, and within what
  double requestedBudget_ = 0.0;
  MapShape shape_;       // what was allocated: requested_, perhaps smaller
  int wrapBorder_ = -1;  // the samplers' wrap mode as last set: 1 border, 0 edge
};

// 1x1 depth textures, 2D array and cube, and a 1x1 float array, bound to sampler units a
// configuration does not use: GL forbids samplers of different types on one unit, so every unit
// gets a texture of its type.
class DummyDepthTextures {
 public:
  void create();
  // With a sampler object whose compare mode matches the shader's sampler type (`compare`: a
  // shadow sampler): WebGL2 refuses a draw that reads a depth texture through the other kind.
  void bindArray(int unit, bool compare) const;
  void bindCube(int unit, bool compare) const;
  void bindMoments(int unit) const;
  void release();

 private:
  gl::TextureName array_, cube_, moments_;
  gl::Sampler raw_, compare_;
};

}  // namespace shadelab

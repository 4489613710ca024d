// Texture-filtering lab: what a texture lookup does when a texel covers many pixels
// (magnification) and when a pixel covers many texels (minification), and what each answer
// costs. Nearest and bilinear within a level, bicubic written in the shader; mip levels chosen
// nearest or blended (trilinear); anisotropic probes along the footprint; an LOD bias and a
// hand-picked level; mip chains made by a box, by a Kaiser-windowed sinc, or by the driver.
// Every filter exists in hardware and written out in filter.glsl, so a student compares the two
// pixel for pixel. All are judged against the same truth: each pixel's footprint integrated by
// 16 x 16 jittered samples of the full-resolution texture, and over a slow camera move, by how
// much more they flicker than the truth does.
// Williams 1983 (pyramidal parametrics); Heckbert 1989 (texture mapping survey); the
// EXT_texture_filter_anisotropic specification; GAMES101 lecture 9.
// Read next: shaders/filtering/filter.glsl, app/scene/mip_chain.h, tutorials/filtering.md.
#pragma once
#include <optional>

#include "app/lab/lab.h"
#include "app/scene/mip_chain.h"

namespace shadelab {

// Tables of names and defines in filtering_lab.cpp.
enum class TexelFilter { Nearest, Bilinear, Bicubic, Count };
enum class MipSelection { Off, NearestLevel, LinearLevel, Count };
enum class MipBuilder { Box, Kaiser, Driver, Count };
enum class FilteringView { Shaded, MipLevel, Anisotropy, Count };

struct FilteringParams {
  TexelFilter filter = TexelFilter::Bilinear;
  MipSelection mipmaps = MipSelection::LinearLevel;  // trilinear
  bool inShader = false;
  int anisotropy = 1;
  float lodBias = 0.0f;
  bool manualLevel = false;
  float level = 0.0f;
  MipBuilder builder = MipBuilder::Box;
  FilteringView view = FilteringView::Shaded;
  bool probe = true;
  float probeX = 0.5f, probeY = 0.45f;  // fractions of the frame, from its top-left corner
  PixelFilter pixelFilter = PixelFilter::Box;
  int motionFrame = 0;
  bool animate = false;
};

// The footprint of one pixel, read back from the GPU: where the texture coordinate moves, in
// texels of level 0, one pixel right (dx) and one pixel up (dy).
struct Footprint {
  glm::vec2 dx{0.0f}, dy{0.0f};
  glm::ivec2 pixel{0};
  bool covered = false;  // the probe pixel shows the texture at all
};

class FilteringLab final : public LabWithParams<FilteringParams>, public Judge {
 public:
  static constexpr int kMotionFrames = 3;  // frames of the slow camera move the flicker is measured over

  std::string_view id() const override { return "filtering"; }
  std::string_view title() const override { return "Texture filtering: bilinear, mipmaps, trilinear, anisotropic"; }
  std::string_view summary() const override;
  std::string_view defaultScene() const override { return "grazing-tiles"; }
  bool animating() const override { return params.animate; }
  std::vector<SceneRecipe> scenes() const override;

  void visitParams(ParamVisitor& v) override;
  SceneNeeds needs() const override;
  std::vector<ProgramSpec> allPrograms() const override;
  InspectedPass inspectedPass() const override { return {"filtering/filtering.frag", "main"}; }

  std::string setup(LabContext& ctx) override;
  void render(Frame& frame) override;
  std::vector<ProgramRef> activePrograms() const override;
  std::vector<std::string> warnings() const override;
  std::vector<LabPanel> panels() const override;

  // Judge: the lab is its own.
  Judge* judge() override { return this; }
  ReferenceSpec reference() const override;
  std::vector<MeasuredView> measuredViews() const override;
  Metrics viewMetrics(const std::vector<ImageF>& images, const std::vector<ImageF>& references) const override;
  std::vector<PlotSpec> plots() const override;
  std::vector<StressCase> stressCases() const override;
  std::vector<SweepAxis> standardSweep() const override;

  // For tests: images decoded since setup (only those a drawn material uses), the last probe.
  int imagesDecoded() const { return imagesDecoded_; }
  const Footprint& footprint() const { return footprint_; }

 private:
  // One texture of the scene, with a mip chain made by one builder.
  struct ChainTexture {
    int image = -1;
    MipBuilder builder = MipBuilder::Box;
    gl::Texture2D texture;
    int levels = 1;
    std::vector<glm::ivec2> sizes;
    std::vector<float> contrast;  // per level: the standard deviation of luminance (linear)
    gl::Texture2D atlas;          // every level side by side, for the chain panel
  };

  ProgramSpec programSpec(const FilteringParams& p, bool probePass) const;
  bool inShader() const;  // bicubic exists only written out
  const ChainTexture* chain(const Scene& scene, int image);
  // Probes along the footprint, as drawn: 1 without mip levels, where every probe would read level 0.
  int anisotropy() const { return params.mipmaps == MipSelection::Off ? 1 : params.anisotropy; }
  void applySampler();
  void makeTexelSampler();
  void probeFootprint(Frame& frame, const glm::mat4& viewProj);
  glm::ivec2 probePixel(glm::ivec2 size) const;  // from the frame's top-left
  glm::mat4 viewMatrix(const Frame& frame) const;

  ShaderLibrary* shaders_ = nullptr;
  ProgramSlot program_, probeProgram_;
  gl::Sampler sampler_;       // the hardware filter, as configured
  gl::Sampler texelSampler_;  // nearest texel of a whole level: what filter.glsl reads through
  gl::RenderTarget probeTarget_;
  gl::Texture2D white_;
  int sceneRevision_ = -1;
  std::vector<std::optional<LinearImage>> decoded_;  // level 0 of each scene image, decoded on first use
  std::vector<ChainTexture> chains_;
  int imagesDecoded_ = 0;
  // From the last frame.
  Footprint footprint_;
  int shown_ = -1;  // index into chains_ of the first drawn texture: the chain panel's
  std::vector<std::string> frameNotes_;
  float maxBias_ = 16.0f;              // the driver's GL_MAX_TEXTURE_LOD_BIAS
  float anisotropyLimit_ = 0.0f;       // the driver's anisotropy limit; 0 before setup (unknown)
  bool slowDriverAnisotropy_ = false;  // gl::Caveat::SlowAnisotropy (gl/driver_caveats.h)
  // Whether the driver's anisotropic filtering is left for the shader's (slowDriverAnisotropy_).
  bool anisotropyMovedToShader() const;
};

}  // namespace shadelab

// Shadows lab: the whole path from a hard shadow map to soft shadows. Acne -> bias -> peter-
// panning -> border and far-plane artifacts -> PCF -> Poisson PCF -> PCSS, for directional,
// spot and point lights, each step measured against ray-traced visibility (Embree).
// Williams, "Casting curved shadows on curved surfaces", 1978; Reeves et al., "Rendering
// antialiased shadows with depth maps", 1987 (PCF); Fernando 2005 (PCSS); Zhang et al. 2006
// (cascades, the practical split scheme); Donnelly and Lauritzen 2006 (VSM); Annen et al. 2008
// (ESM); Lauritzen and McCool 2008 (EVSM).
// Read next: shaders/shadows/shadow_filters.glsl, tutorials/shadows.md.
#pragma once
#include <array>
#include <bit>
#include <memory>
#include <optional>
#include <span>

#include "app/lab/lab.h"
#include "labs/shadows/depth_range.h"
#include "labs/shadows/gpu_tracer.h"
#include "labs/shadows/light_rig.h"
#include "labs/shadows/shadow_map.h"

namespace shadelab {

class RayScene;

// The filters and views, and what each needs, are tables in shadow_options.h.
enum class ShadowFilter { Hard, HardwarePcf, Pcf, Poisson, Pcss, Vsm, Esm, Evsm, PcfBilinear, Count };
enum class ShadowView {
  Shaded,
  Visibility,
  BiasHeat,
  TexelDensity,
  PcssBlocker,
  PcssPenumbra,
  Cascades,
  DepthRaw,
  DepthLinear,
  Count
};
enum class DepthFormat { D16, D24, D32F, Count };
enum class MapFit { Scene, View, Cascades, DepthRange, Count };  // directional maps: what the map covers
enum class TruthTracer { Auto, Embree, Gpu, Count };             // who traces the ray-traced truth

// One nested struct per section of the panel, each visited by its own function (shadows_lab.cpp).
struct ShadowsParams {
  struct KeyLight : LightPlacement {  // where the key light is (light_rig.h), and:
    bool casts = true;
    bool sceneLight = true;  // a scene with a light of its own (learnopengl) sets the direction
  } key;
  struct FillLight {  // a second, spot light
    bool on = false;
    bool casts = true;
  } fill;
  struct Map : LightFrustum {  // the frustum when auto-fit is off (light_rig.h), and:
    int sizeIndex = 3;         // 256 << index: 256 .. 8192
    DepthFormat format = DepthFormat::D24;
    MapFit fit = MapFit::Scene;  // directional, auto-fit: the scene, the view, cascades over its frustum or its depth
    int cascadeCount = 4;        // fit = cascades or depth-range: 2..4 maps of map_size^2 each
    float splitLambda = 0.75f;   // 0: uniform splits, 1: logarithmic
    float cascadeBlend = 0.1f;   // fraction of a cascade's range blended into the next
    bool snapTexels = true;      // fitted maps move by whole texels: no shimmer as the camera moves
    bool borderClamp = true;     // outside the map: lit (border depth 1) instead of the edge texel
    bool farFix = true;          // beyond the far plane: lit instead of shadowed
    bool cullFront = false;      // depth pass draws back faces only
    bool sixCubePasses = false;  // point light: six passes instead of one geometry-shader pass

    int size() const { return 256 << sizeIndex; }
    static constexpr int sizeIndexOf(int size) { return std::countr_zero(unsigned(size / 256)); }
  } map;
  struct Bias {
    float constant = 2.5f;      // texels (the floor of the slope-scaled bias)
    float slope = 4.0f;         // texels, k in max(k (1 - N.L), constant)
    float normalOffset = 0.0f;  // texels along the normal
    float offsetFactor = 0.0f;  // glPolygonOffset factor
    float offsetUnits = 0.0f;   // glPolygonOffset units
    bool receiverPlane = true;  // filter taps compare against the receiver plane at each tap
  } bias;
  struct Filter {
    ShadowFilter type = ShadowFilter::Pcf;
    int pcfSize = 3;              // N in N x N (compile-time loop bound)
    int poissonIndex = 1;         // 8 << index samples: 8, 16, 32, 64
    float poissonRadius = 2.0f;   // texels
    bool rotateSamples = true;    // per-pixel rotation of the Poisson disk
    int blockerIndex = 1;         // PCSS blocker search samples: 8 << index
    int pcssIndex = 1;            // PCSS filter samples: 8 << index (16: on the error-cost front)
    int blurRadius = 2;           // filtered maps: Gaussian blur, texels each way (0: no blur pass)
    bool momentMips = true;       // filtered maps: mipmapped, sampled trilinear
    float minVariance = 1e-5f;    // VSM/EVSM: variance floor (in normalised depth squared)
    float bleedReduction = 0.3f;  // VSM: p -> (p - a) / (1 - a)
    float esmExponent = 60.0f;    // ESM: c in exp(c t)
    float evsmPositive = 30.0f;   // EVSM: exponents of the positive and negative warps
    float evsmNegative = 8.0f;
  } filter;
  struct View {
    ShadowView mode = ShadowView::Shaded;
    int depthLight = 0;    // the map the depth views show: 0 key, 1 fill
    int depthCascade = 0;  // ... and which cascade of the key light's
    float depthZoom = 1.0f;
    float depthCentreU = 0.5f;
    float depthCentreV = 0.5f;
    bool frameFaces = true;  // a cube's faces each zoomed to the geometry they see
    bool showFrustum = false;
  } view;
  struct Truth {
    TruthTracer tracer = TruthTracer::Auto;
  } truth;
  struct SceneSettings {
    int tessellation = 48;
    float scale = 1.0f;
    bool floorUnderFiles = true;  // a mesh from a file stands on a floor: its shadow has a receiver
  } scene;
};

// The part of each face of a cube map centred at `light` that the boxes project to, as (centre,
// half size) in the face's [-1, 1]^2 (the depth view's cross order: -X +Z +X -Z +Y -Y); (0, 0, 0)
// where a face sees none of them. frame = false: every face whole.
std::array<glm::vec3, 6> cubeFaceWindows(std::span<const Bounds> boxes, glm::vec3 light, bool frame);

class ShadowsLab final : public LabWithParams<ShadowsParams>, public Judge {
 public:
  ShadowsLab();
  ~ShadowsLab() override;

  std::string_view id() const override { return "shadows"; }
  std::string_view title() const override { return "Shadows: maps, bias, PCF, PCSS"; }
  std::string_view summary() const override;
  std::string_view defaultScene() const override { return "shadow-test"; }
  std::vector<SceneRecipe> scenes() const override;

  void visitParams(ParamVisitor& v) override;
  SceneNeeds needs() const override;
  std::vector<ProgramSpec> allPrograms() const override;
  InspectedPass inspectedPass() const override { return {"shadows/lit.frag", "main"}; }

  std::string setup(LabContext& ctx) override;
  void render(Frame& frame) override;
  std::vector<ProgramRef> activePrograms() const override;
  std::vector<std::string> warnings() const override;

  // Judge: the lab is its own.
  Judge* judge() override { return this; }
  ReferenceSpec reference() const override;
  TraceWork traceReference(Frame& frame) override;
  GlTraceStep traceReferenceOnGl(Frame& frame) override;
  Settings measuredView() const override { return {{"view", "visibility"}}; }
  Metrics metrics(const ImageF& image, const ImageF& reference) const override;
  std::vector<PlotSpec> plots() const override {
    return {{"visibility_rmse_hard"}, {"visibility_rmse_area"}, {"misclassified_pct"}};
  }
  Settings metricNotes() const override;
  std::vector<StressCase> stressCases() const override;
  std::vector<SweepAxis> standardSweep() const override;

  // The filter the programs use: filtered maps need a 2D map, so a point light gets 3x3 PCF.
  ShadowFilter effectiveFilter() const;
  // The key light's maps in the last frame: one, or one per cascade (tests, the Cascades panel).
  const std::vector<Cascade>& cascades() const { return cascades_; }
  // fit = depth-range: the view depths the last frame's cascades were split over, as the frame
  // before drew them; none when there was no such frame from the same camera.
  std::optional<glm::vec2> drawnRange() const { return drawnRange_; }
  const ShadowMap& keyMap() const { return keyMap_; }
  const ShadowMap& fillMap() const { return fillMap_; }
  // Every program the current settings can draw with (a subset of allPrograms()'s, as tests check).
  std::vector<ProgramSpec> currentPrograms() const;
  // ... the same from the settings alone (`sixPasses`: the point light's map drawn in six passes).
  static std::vector<ProgramSpec> programsOf(const ShadowsParams& p, bool sixPasses);
  // The parameters of `p`, as visitParams lists them (`sceneLit`: the scene has a light of its own).
  static void visitParamsOf(ParamVisitor& v, ShadowsParams& p, bool sceneLit);
  // The unit-disk samples the shaders get for `count` taps (8, 16, 32, 64).
  static const std::vector<glm::vec2>& disk(int count);
  // How the GPU tracer cuts its work (BM_GpuTruthShape tries each on the machine at hand); the
  // tracer, once a truth has been asked of it.
  void setTracerShape(GpuShadowTracer::Shape shape);
  const GpuShadowTracer* gpuTracer() const { return tracer_.get(); }

 private:
  enum class InternalView { None, Position, Normal };  // G-buffer for the ray-traced reference
  LightSetup keySetup() const;
  LightSetup fillSetup() const;
  static ProgramSpec litSpec(const ShadowsParams& p, InternalView internal);
  static ProgramSpec depthSpec(bool cube, bool sixPasses, ShadowFilter filter);
  static ProgramSpec blurSpec();
  static ProgramSpec depthViewSpec(const ShadowsParams& p);
  void setFilterUniforms(Program& prog) const;
  void renderKeyMaps(Frame& frame, const LightFrame& key, const DepthPassState& state, GLenum format);
  void drawDepthView(Frame& frame, const LightFrame& key, const LightFrame& fill);
  Program& fetch(size_t slot, const ProgramSpec& spec) { return programs_[slot].get(*shaders_, spec); }
  static ProgramSpec linesSpec();
  void drawLit(Frame& frame, Program& prog, const LightFrame& key, const LightFrame* fill);
  void drawFrustum(Frame& frame, const LightFrame& key);

  ShaderLibrary* shaders_ = nullptr;
  std::vector<ProgramSlot> programs_;  // one per role: lit, key depth, fill depth, depth view, lines
  ShadowMap keyMap_, fillMap_;
  DepthRange depthRange_;                // fit = depth-range: what the camera drew, for the next frame's cascades
  std::optional<glm::vec2> drawnRange_;  // ... and the range this frame's cascades were split over, if any
  DummyDepthTextures dummies_;
  gl::VertexArray emptyVao_, frustumVao_;
  gl::Buffer frustumVbo_;
  std::vector<Cascade> cascades_;           // the key light's maps, as last rendered
  std::vector<int> boundSamplers_;          // units drawLit bound sampler objects to
  glm::vec3 sceneLight_{0.0f};              // the current scene's own light, if it has one
  std::vector<std::string> lightWarnings_;  // from the last render's light setup
  std::vector<std::string> mapWarnings_;    // maps the driver could only allocate smaller, this frame
  // Allocates `map` for `shape` within `budgetBytes` (what the lab's other maps leave of
  // ShadowMap::kBudgetBytes); false when no map could be had. A map smaller than asked is drawn
  // with a warning naming both sizes.
  bool ensureMap(ShadowMap& map, const MapShape& shape, const char* which, double budgetBytes);
  // The size a map was allocated at (the texel size the shaders use), or the asked size if none.
  int sizeOf(const ShadowMap& map) const { return map ? map.size() : params.map.size(); }
  std::shared_ptr<const RayScene> rayScene_;  // shared with a trace job still running
  std::unique_ptr<GpuShadowTracer> tracer_;   // truth_tracer = gpu
  GpuShadowTracer::Shape tracerShape_;
  bool softwareRenderer_ = true;  // the context draws in software (gl::softwareRenderer)
  bool geometryShaders_ = true;   // the context has them (not WebGL2): else six cube passes
  bool sixCubePasses() const { return params.map.sixCubePasses || !geometryShaders_; }
  // truth_tracer = auto resolved: the GPU tracer unless the context draws in software.
  bool tracesOnGpu() const {
    return params.truth.tracer == TruthTracer::Gpu || (params.truth.tracer == TruthTracer::Auto && !softwareRenderer_);
  }
  GpuShadowTracer::Programs tracePrograms_;
  // The GPU trace's area truth: its standard error (mean over its pixels) as of the last read-back,
  // and the sample count it was read at.
  double standardError_ = 0.0;
  int errorAt_ = 0;
  int rayRevision_ = -1;
  InternalView internalView_ = InternalView::None;
};

}  // namespace shadelab

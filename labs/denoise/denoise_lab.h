// Denoising lab: Laplacian smoothing along normals with a live lambda, the stiff and the stable
// ways to step it, a feature-preserving filter beside it, and the homework's bake of the result
// into a displacement map (nearest vertex by FLANN, or rasterised in UV space) rendered back with
// a vertex shader: where it cracks along UV seams and why, and the crack-free path beside it.
// Every result is judged against the clean mesh (the Guided Mesh Normal Filtering metric).
// Taubin 1995; Desbrun et al. 1999; Zheng et al. 2011; Zhang et al. 2015.
// Read next: labs/denoise/laplacian.h, shaders/denoise/mesh.vert, tutorials/denoise.md.
#pragma once
#include <bit>
#include <memory>
#include <optional>

#include "app/lab/lab.h"
#include "labs/denoise/denoise_pipeline.h"
#include "labs/denoise/gpu_smoother.h"

namespace shadelab {

enum class NoiseSource { Published, Generated, Count };
inline constexpr Named<NoiseSource> kNoiseSources[] = {{NoiseSource::Published, "published"},
                                                       {NoiseSource::Generated, "generated"}};
static_assert(coversEnum<NoiseSource>(kNoiseSources));
// What the view shows, with the pass that draws it (compare draws four panels of its own).
enum class DenoiseShow { Smoothed, Noisy, Clean, Map, Attribute, Compare, Count };
struct DenoiseShowRow {
  DenoiseShow value;
  std::string_view name;
  std::string_view pass;
};
inline constexpr DenoiseShowRow kDenoiseShows[] = {
    {DenoiseShow::Smoothed, "smoothed", "draw: smoothed"},
    {DenoiseShow::Noisy, "noisy", "draw: noisy"},
    {DenoiseShow::Clean, "clean", "draw: clean"},
    {DenoiseShow::Map, "map", "draw: map path"},
    {DenoiseShow::Attribute, "attribute", "draw: attribute path"},
    {DenoiseShow::Compare, "compare", ""}};  // compare: four panels, each its own pass
static_assert(coversEnum<DenoiseShow>(kDenoiseShows));
enum class DenoiseView { Shaded, Error, Offset, SeamGap, Count };
inline constexpr Named<DenoiseView> kDenoiseViews[] = {{DenoiseView::Shaded, "shaded"},
                                                       {DenoiseView::Error, "error"},
                                                       {DenoiseView::Offset, "offset"},
                                                       {DenoiseView::SeamGap, "seam-gap"}};
static_assert(coversEnum<DenoiseView>(kDenoiseViews));

// One nested struct per section of the panel, each visited by its own function (denoise_lab.cpp).
// The pipeline's own settings structs (noise, smoothing, bilateral, bake) live in the sections and
// reach the pipeline whole: config() gathers them, and the few switches beside them, into one
// DenoiseConfig, the only copy the CPU and GPU smoothers read.
struct DenoiseParams {
  struct Input {                                  // the noisy input
    NoiseSource source = NoiseSource::Published;  // the data set's noisy twin, where there is one
    std::string clean;                            // a user's clean reference for the scene's (noisy) mesh; "": none
    NoiseSettings noise;                          // generated noise (mesh_noise.h)
  } input;
  struct Smoothing {
    SmoothingSettings settings;   // the method, and the Laplacian steps' lambda, weights, iterations (laplacian.h)
    BilateralSettings bilateral;  // sigma_r and the normal passes (its vertex passes are settings.iterations)
    bool weld = true;             // smoothing on the welded surface (off: the seam bug)
    bool preserveVolume = false;  // rescale the result to the input's volume (closed meshes)
    SmoothingDevice device = SmoothingDevice::Cpu;  // explicit and Taubin steps on the GPU, or here
    bool cpuReference = true;                       // with the GPU's steps, the CPU's beside them
  } smoothing;
  struct Map {             // the displacement map
    int sizeIndex = 4;     // 64 << index: 64 .. 4096
    BakeSettings bake;     // method, FLANN checks, gutter, format (displacement_bake.h)
    bool bilinear = true;  // how the vertex shader samples the map

    static constexpr int sizeIndexOf(int size) { return std::countr_zero(unsigned(size / 64)); }
  } map;
  struct View {
    DenoiseShow show = DenoiseShow::Smoothed;
    DenoiseView mode = DenoiseView::Shaded;
    float heatScale = 0.5f;  // mean edge lengths at full colour (error, seam gap); offsets: twice that
  } view;
};

class DenoiseLab final : public LabWithParams<DenoiseParams>, public Judge {
 public:
  DenoiseLab();
  ~DenoiseLab() override;

  std::string_view id() const override { return "denoise"; }
  std::string_view title() const override { return "Denoising: Laplacian, bilateral, displacement bake"; }
  std::string_view summary() const override;
  std::string_view defaultScene() const override;
  std::vector<SceneRecipe> scenes() const override;

  void visitParams(ParamVisitor& v) override;
  SceneNeeds needs() const override;
  std::vector<ProgramSpec> allPrograms() const override;
  InspectedPass inspectedPass() const override { return {"denoise/mesh.frag", "main"}; }

  std::string setup(LabContext& ctx) override;
  void update(const Scene& scene, float dt) override;
  void render(Frame& frame) override;
  std::vector<ProgramRef> activePrograms() const override;
  std::vector<std::string> warnings() const override;
  std::vector<LabPanel> panels() const override;

  // Judge: the lab is its own.
  Judge* judge() override { return this; }
  ReferenceSpec reference() const override;
  Metrics meshMetrics() const override;
  std::vector<PlotSpec> plots() const override;
  std::vector<StressCase> stressCases() const override;
  std::vector<SweepAxis> standardSweep() const override;

 private:
  // How the mesh program takes its positions: each path a program of its own, named and defined here.
  enum class Path { Plain, Map, Attribute, SmoothedOnGpu, Count };
  static constexpr NamedDefine<Path> kPaths[] = {{Path::Plain, "plain", ""},
                                                 {Path::Map, "map", "DISPLACE_MAP"},
                                                 {Path::Attribute, "attribute", "DISPLACE_ATTRIBUTE"},
                                                 {Path::SmoothedOnGpu, "smoothed-on-gpu", "SMOOTHED_ON_GPU"}};
  static_assert(coversEnum<Path>(kPaths));
  DenoiseConfig config() const;
  static ProgramSpec programSpec(DenoiseView view, Path path);
  void rebuildModel(const Scene& scene);
  void upload(DenoiseResult result);
  void uploadViewData();                        // the positions and heat scalars the current show and view draw
  enum class Style { Surface, Ghost, Marker };  // mesh.frag's u_style
  void drawPanel(Frame& frame, Path path, const GpuMesh& mesh, glm::ivec4 viewport, Style style = Style::Surface);
  std::string saveMap();  // the bake action
  bool smoothsOnGpu(const DenoiseConfig& c) const;
  // The job that computes `want`, with the GPU's smoothing where it ran (else it smooths itself).
  void submit(const DenoiseConfig& want, std::shared_ptr<const SmoothedElsewhere> smoothed);
  // The explicit or Taubin steps of `c` on the GPU, on the GL thread, for the job that does the rest.
  SmoothedElsewhere smoothOnGpu(const DenoiseConfig& c);

  ShaderLibrary* shaders_ = nullptr;
  JobRunner* jobs_ = nullptr;
  ProgramSlot programs_[4];  // by Path
  int modelRevision_ = -1;   // scene revision the model was built from
  std::string modelScene_;
  bool sceneIsFile_ = false;  // a user's file, not one of the lab's scenes
  std::string missingPairs_;  // the published pairs not on disk, as of the last model build (warnings() runs per frame)
  std::string modelClean_;    // the clean file it was built with ("" : the scene is the clean mesh)
  std::string pairNote_;      // how the scene and the clean file were paired, or ""
  double pairMoveEdges_ = 0.0;
  std::shared_ptr<const DenoiseModel> model_;
  std::string modelNote_;
  std::optional<DenoiseConfig> requested_;  // what the job in flight (or the last one) computes
  std::unique_ptr<DenoiseResult> result_;   // the last result delivered: drawn until the next arrives
  GpuMesh plainMesh_, mapMesh_, attributeMesh_;
  GpuSmoother gpu_;
  std::string gpuUnavailable_;  // why this context cannot smooth on the GPU, or ""
  // What the smoother holds: the mesh of a model (welded or not) and the input noise on it.
  struct GpuInput {
    int model = -1;
    bool weld = true, published = true;
    NoiseSettings noise;
    bool operator==(const GpuInput&) const = default;
  };
  std::optional<GpuInput> gpuInput_;
  // The smoother's last run is newer than the result drawn: the smoothed mesh is drawn from its
  // texture (no read-back) until the job's result arrives; plainMesh_'s kScalar0 holds each
  // vertex's texel index there (set with the smoother's mesh).
  bool gpuDrawn_ = false;
  gl::Texture2D mapTexture_, mapPreview_;
  std::string lastAction_;
  // What the GPU meshes hold now: re-uploaded when the show or view changes, not per frame.
  DenoiseShow uploadedShow_ = DenoiseShow::Smoothed;
  DenoiseView uploadedView_ = DenoiseView::Shaded;
};

}  // namespace shadelab

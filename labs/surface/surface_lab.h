// Surface-detail lab: normal mapping, bump mapping, displacement (on a subdivided mesh, and by
// tessellation) and the parallax family, all judged against one truth: the height field applied
// to a very finely subdivided mesh, normals from the field, supersampled. The wrong steps a student
// takes on the way (adding the perturbation to the old normal, skipping a normalisation, an sRGB
// or DirectX-green decode, a frame not made orthogonal again) are toggles with a one-line reason,
// and the tangent frame has three sources to compare: the mesh's own, generated, per pixel.
// Blinn 1978 (bump); Cohen et al. 1998 (normal maps); Kaneko et al. 2001 (parallax);
// Tatarchuk 2006 (parallax occlusion mapping); Mikkelsen 2008 (tangent frames).
// Read next: shaders/surface/surface.frag, shaders/surface/height.glsl, tutorials/surface.md.
#pragma once
#include "app/lab/lab.h"
#include "app/lab/technique.h"
#include "labs/surface/surface_geometry.h"

namespace shadelab {

enum class SurfaceTechnique {
  None,
  NormalMap,
  Bump,
  Displacement,
  Tessellation,
  Parallax,
  SteepParallax,
  Pom,
  Truth,
  Count
};

// What a technique changes: the shading normal, the texture lookup (parallax), or the mesh itself
// (on the CPU's subdivision, the GPU's, or as the truth).
enum class SurfaceChange { Nothing, Normal, Lookup, Geometry };

// The techniques: a new one is its row here, its branch in surface.frag (under its define) and its test.
struct SurfaceTechniqueRow {
  SurfaceTechnique value;
  std::string_view name;    // --set surface.technique=NAME
  std::string_view define;  // what surface.vert/.frag test ("": nothing of its own)
  SurfaceChange changes;
  bool needsHeight;  // reads the height map
};
inline constexpr SurfaceTechniqueRow kSurfaceTechniques[] = {
    {SurfaceTechnique::None, "none", "", SurfaceChange::Nothing, false},
    {SurfaceTechnique::NormalMap, "normal-map", "NORMAL_MAP", SurfaceChange::Normal, false},
    {SurfaceTechnique::Bump, "bump", "BUMP", SurfaceChange::Normal, true},
    {SurfaceTechnique::Displacement, "displacement", "DISPLACE_VERTEX", SurfaceChange::Geometry, true},
    {SurfaceTechnique::Tessellation, "tessellation", "", SurfaceChange::Geometry, true},  // its stages displace
    {SurfaceTechnique::Parallax, "parallax", "PARALLAX", SurfaceChange::Lookup, true},
    {SurfaceTechnique::SteepParallax, "steep-parallax", "STEEP", SurfaceChange::Lookup, true},
    {SurfaceTechnique::Pom, "pom", "POM", SurfaceChange::Lookup, true},
    {SurfaceTechnique::Truth, "truth", "DISPLACE_VERTEX", SurfaceChange::Geometry, true},
};
static_assert(coversEnum<SurfaceTechnique>(kSurfaceTechniques));

inline bool isParallax(SurfaceTechnique t) { return rowOf(kSurfaceTechniques, t).changes == SurfaceChange::Lookup; }
inline bool isDisplacing(SurfaceTechnique t) { return rowOf(kSurfaceTechniques, t).changes == SurfaceChange::Geometry; }
enum class SurfaceAt { Top, Bottom, Count };
enum class GreenConvention { OpenGl, DirectX, Count };
enum class MapDecoding { Linear, Srgb, Count };
enum class TextureFilter { Nearest, Bilinear, Trilinear, Anisotropic, Count };  // kTextureFilters in surface_lab.cpp
enum class BumpForm { Consistent, Games101, Count };
enum class DisplacedNormals { FromHeight, Unchanged, PerVertex, Count };
enum class SurfaceView { Shaded, Normals, TangentAngle, Height, Uv, Count };
inline constexpr NamedDefine<SurfaceView> kSurfaceViews[] = {
    {SurfaceView::Shaded, "shaded", "VIEW_SHADED"},
    {SurfaceView::Normals, "normals", "VIEW_NORMALS"},
    {SurfaceView::TangentAngle, "tangent-angle", "VIEW_TANGENT_ANGLE"},
    {SurfaceView::Height, "height", "VIEW_HEIGHT"},
    {SurfaceView::Uv, "uv", "VIEW_UV"},
};
static_assert(coversEnum<SurfaceView>(kSurfaceViews));

struct SurfaceParams {
  SurfaceTechnique technique = SurfaceTechnique::Pom;
  float heightScale = 0.04f;  // world units for a height of 1 (the procedural maps are baked for 0.04)
  SurfaceAt surfaceAt = SurfaceAt::Top;
  HeightConvention heightMap = HeightConvention::AsLoaded;
  float normalStrength = 1.0f;
  GreenConvention green = GreenConvention::OpenGl;
  MapDecoding decoding = MapDecoding::Linear;
  TextureFilter filter = TextureFilter::Trilinear;
  BumpForm bumpForm = BumpForm::Consistent;
  float kh = 0.2f, kn = 0.1f;  // GAMES101 assignment 3's values
  int subdivision = 6;         // midpoint levels for vertex displacement
  int tessLevel = 16;
  DisplacedNormals displacedNormals = DisplacedNormals::FromHeight;
  int layers = 16;  // steep parallax / POM depth slices
  bool selfShadow = false;
  TangentSource tangents = TangentSource::Generated;
  TangentSource compareWith = TangentSource::Screen;
  float angleScale = 10.0f;  // degrees at full colour in the tangent-angle view
  bool overlay = false;
  float overlayLength = 2.0f;
  bool addToOldNormal = false;
  bool noRenormalize = false;
  bool noOrthogonalize = false;
  float lightElevationDeg = 20.0f;  // low: relief casts visible shade
  float lightAzimuthDeg = -40.0f;
  SurfaceView view = SurfaceView::Shaded;
  int tessellation = 64;  // segments of the brick sphere
};

class SurfaceLab final : public LabWithParams<SurfaceParams>, public Judge {
 public:
  static constexpr int kMaxTriangles = 2'500'000;  // subdivision stops before this (memory, llvmpipe)

  std::string_view id() const override { return "surface"; }
  std::string_view title() const override { return "Surface detail: normal, bump, displacement, parallax"; }
  std::string_view summary() const override;
  std::string_view defaultScene() const override { return "bricks"; }
  std::vector<SceneRecipe> scenes() const override;

  void visitParams(ParamVisitor& v) override;
  SceneNeeds needs() const override;
  std::vector<ProgramSpec> allPrograms() const override;
  InspectedPass inspectedPass() const override { return {"surface/surface.frag", "main"}; }

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

 private:
  ProgramSpec programSpec(const SurfaceParams& p, bool hasUvs) const;
  static ProgramSpec overlaySpec();
  bool needsTangents() const;
  int levelFor(const Scene& scene) const;  // subdivision level the current technique draws at
  int tessLevelFor(const Scene& scene);    // the tessellation level drawn: the asked one, held to the triangle cap
  void measureUvShear(const Scene& scene);
  void noteHeightless(const Frame& frame, std::span<const SurfaceDraw> draws);
  void drawSurface(Frame& frame, const SurfaceDraw& d, int tessLevel, glm::vec3 lightDir);
  void drawTangentFrames(Frame& frame, SurfaceGeometryKey key);

  ShaderLibrary* shaders_ = nullptr;
  ProgramSlot program_, overlay_;
  SurfaceGeometry geometry_;
  gl::Texture2D whiteMap_, flatNormalMap_, topHeightMap_;  // stand-ins where a material has none
  // The height field is geometry, not a picture: trilinear (the parallax marches ask for whole
  // levels, surface/height.glsl), never anisotropic (16 taps per lookup of a 64-step parallax
  // march is what turned one llvmpipe frame into 18 seconds).
  gl::Sampler heightSampler_;
  // From the last frame: what was drawn and what the student should know about it.
  std::vector<std::string> frameNotes_;
  std::string heightless_;  // a drawn material with UVs but no height field ("" : none): no truth exists
  size_t drawnTriangles_ = 0;
  int drawnLevel_ = 0;
  // The scene's UV shear (where generated and screen-space tangents part), per scene build.
  int shearRevision_ = -1;
  float shearMedian_ = 0.0f, shearP90_ = 0.0f;
};

}  // namespace shadelab

#include "labs/surface/surface_lab.h"

#include <algorithm>
#include <cmath>
#include <set>

#include <glm/gtc/matrix_inverse.hpp>

#include "app/lab/technique.h"
#include "app/lab/variants.h"
#include "labs/surface/subdivide.h"
#include "labs/surface/surface_scenes.h"

namespace shadelab {
namespace {

constexpr Named<SurfaceAt> kSurfaceAt[] = {{SurfaceAt::Top, "top"}, {SurfaceAt::Bottom, "bottom"}};
static_assert(coversEnum<SurfaceAt>(kSurfaceAt));
constexpr Named<HeightConvention> kHeightConventions[] = {{HeightConvention::AsLoaded, "as-loaded"},
                                                          {HeightConvention::Height, "height"},
                                                          {HeightConvention::Depth, "depth"}};
static_assert(coversEnum<HeightConvention>(kHeightConventions));
constexpr Named<GreenConvention> kGreen[] = {{GreenConvention::OpenGl, "opengl"},
                                             {GreenConvention::DirectX, "directx"}};
static_assert(coversEnum<GreenConvention>(kGreen));
constexpr Named<MapDecoding> kDecoding[] = {{MapDecoding::Linear, "linear"}, {MapDecoding::Srgb, "srgb"}};
static_assert(coversEnum<MapDecoding>(kDecoding));
// How the colour and normal maps are sampled.
struct TextureFilterRow {
  TextureFilter value;
  std::string_view name;
  GLenum minFilter, magFilter;
  float anisotropy;
};
constexpr TextureFilterRow kTextureFilters[] = {
    {TextureFilter::Nearest, "nearest", GL_NEAREST, GL_NEAREST, 1.0f},
    {TextureFilter::Bilinear, "bilinear", GL_LINEAR, GL_LINEAR, 1.0f},
    {TextureFilter::Trilinear, "trilinear", GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, 1.0f},
    {TextureFilter::Anisotropic, "anisotropic", GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, 16.0f},
};
static_assert(coversEnum<TextureFilter>(kTextureFilters));
constexpr Named<BumpForm> kBumpForms[] = {{BumpForm::Consistent, "consistent"}, {BumpForm::Games101, "games101"}};
static_assert(coversEnum<BumpForm>(kBumpForms));
constexpr Named<DisplacedNormals> kDisplacedNormals[] = {{DisplacedNormals::FromHeight, "from-height"},
                                                         {DisplacedNormals::Unchanged, "unchanged"},
                                                         {DisplacedNormals::PerVertex, "per-vertex"}};
static_assert(coversEnum<DisplacedNormals>(kDisplacedNormals));
constexpr Named<TangentSource> kSources[] = {
    {TangentSource::Generated, "generated"}, {TangentSource::Mesh, "mesh"}, {TangentSource::Screen, "screen"}};
static_assert(coversEnum<TangentSource>(kSources));

// Texture units of surface.frag's samplers.
enum Unit { kColorUnit = 0, kNormalUnit = 1, kHeightUnit = 2 };

bool usesHeight(SurfaceTechnique t) { return rowOf(kSurfaceTechniques, t).needsHeight; }

gl::Texture2D onePixel(const uint8_t rgba[4]) {
  gl::SamplerState s;
  s.minFilter = s.magFilter = GL_NEAREST;
  return gl::Texture2D::fromRgba8({1, 1}, rgba, s, false);
}

}  // namespace

std::string_view SurfaceLab::summary() const {
  return "A flat wall made to look like bricks, five ways. Normal and bump mapping change only the normal; "
         "displacement moves the geometry (a subdivided mesh, or tessellation); parallax mapping moves the texture "
         "lookup as if the wall had depth. Each is measured against the truth: the height field on a very fine "
         "mesh, supersampled. Tick a wrong step to see the mistake a student makes, and look at the tangent-angle "
         "view to see where two tangent frames disagree.";
}

std::vector<SceneRecipe> SurfaceLab::scenes() const { return surfaceScenes(); }

void SurfaceLab::visitParams(ParamVisitor& v) {
  auto& p = params;
  v.section("Technique");
  v.enumParam({"technique", "Technique", "",
               "none: the mesh's own normal; normal-map; bump: a normal from the height "
               "field's slope; displacement: vertices moved on a subdivided mesh; tessellation: the same on the GPU; "
               "parallax, steep-parallax, pom: texture lookups moved as if the surface had depth; truth: the field on "
               "a very fine mesh, what the others are judged against."},
              p.technique, namesOf<kSurfaceTechniques>());
  v.floatParam({"height_scale", "Height scale", "world",
                "World units of relief for a height of 1 (negative: dents "
                "for bumps). The procedural maps are baked for 0.04."},
               p.heightScale, -2.0f, 2.0f);
  v.enumParam({"surface_at", "Surface at", "",
               "top: the polygon is the top of the height field and mortar is recessed "
               "(parallax mapping's convention); bottom: p' = p + n s h, bricks stand out (the GAMES101 form)."},
              p.surfaceAt, namesOf<kSurfaceAt>());
  v.enumParam({"height_map", "Height map reads", "",
               "as-loaded: as the material says (an MTL disp map is a height, "
               "white = high; LearnOpenGL's bricks2_disp is a depth map); height; depth: white = deep, height = 1 - "
               "value (LearnOpenGL's convention, for its maps in your own MTL)."},
              p.heightMap, namesOf<kHeightConventions>());
  v.section("Normal map");
  v.floatParam({"normal_strength", "Strength", "", "Scales the map's x and y: 1 as baked."}, p.normalStrength, 0.0f,
               4.0f);
  v.enumParam({"green", "Green channel", "",
               "opengl: +Y along +v (how these maps are made); directx: +Y along -v. The "
               "wrong one lights every brick from the other side vertically."},
              p.green, namesOf<kGreen>());
  v.enumParam({"decoding", "Decoding", "",
               "linear: the map's numbers as they are; srgb: decoded as a colour (a "
               "wrong step: vectors bend towards the tangent plane)."},
              p.decoding, namesOf<kDecoding>());
  v.enumParam({"filter", "Texture filter", "",
               "nearest, bilinear, trilinear (mipmapped) or 16x anisotropic, for the "
               "colour and normal maps (the height field, being geometry, is read trilinearly; "
               "the parallax marches read its nearest mip level)."},
              p.filter, namesOf<kTextureFilters>());
  v.section("Bump");
  v.enumParam({"bump_form", "Bump form", "",
               "consistent: the slope in world units from the height scale and the mesh's "
               "UV scale, agreeing with displacement; games101: dU = kh kn (h(u + 1/w, v) - h(u, v)), as in the "
               "assignment."},
              p.bumpForm, namesOf<kBumpForms>());
  v.floatParam({"kh", "kh", "", "GAMES101 height scale."}, p.kh, 0.0f, 50.0f);
  v.floatParam({"kn", "kn", "", "GAMES101 normal scale."}, p.kn, 0.0f, 50.0f);
  v.section("Displacement");
  v.intParam({"subdivision", "Subdivision", "levels",
              "Midpoint subdivisions of the mesh for vertex displacement (each "
              "quadruples the triangles; capped at 2.5 M)."},
             p.subdivision, 0, 10);
  v.intParam({"tess_level", "Tessellation level", "", "Parts per patch edge and inside, 1..64."}, p.tessLevel, 1, 64);
  v.enumParam(
      {"displaced_normals", "Displaced normals", "",
       "from-height: the normal from the height field's slope, "
       "per pixel; unchanged: the base mesh's, so the displaced bricks are lit like a flat wall; per-vertex: the "
       "slope's normal computed at each vertex (surface/displace.glsl) and interpolated, as fine as the mesh "
       "(displacement only: the tessellated surface takes from-height)."},
      p.displacedNormals, namesOf<kDisplacedNormals>());
  v.section("Parallax");
  v.intParam({"layers", "Layers", "", "Depth slices the steep parallax and POM march through (the loop's bound)."},
             p.layers, 1, 128);
  v.boolParam({"self_shadow", "Self-shadowing", "",
               "The parallax family marches from the point found towards the "
               "light: bricks shadow the mortar. The truth is then shadowed too (the height field marched half a "
               "texel at a time); the other techniques cannot shadow themselves and are judged against it."},
              p.selfShadow);
  v.section("Tangent frame");
  v.enumParam({"tangents", "Tangent source", "",
               "generated: per vertex, angle-weighted, split where mirrored UVs meet "
               "(MikkTSpace's way); mesh: the file's own (glTF TANGENT); screen: per pixel, from screen-space "
               "derivatives."},
              p.tangents, namesOf<kSources>());
  v.enumParam({"compare_with", "Compare with", "", "The other source for the tangent-angle view."}, p.compareWith,
              namesOf<kSources>());
  v.floatParam({"angle_scale", "Angle scale", "deg", "Tangent-angle view: the angle drawn at full colour (yellow)."},
               p.angleScale, 0.1f, 90.0f, true);
  v.boolParam({"overlay", "Show T, B, N", "", "Draw each vertex's frame: tangent red, bitangent green, normal blue."},
              p.overlay);
  v.floatParam({"overlay_length", "Frame length", "",
                "Length of the drawn frames, in units of the smaller of 4 % of the "
                "scene's size and half a mean edge."},
               p.overlayLength, 0.1f, 10.0f, true);
  v.section("Wrong steps");
  v.boolParam({"add_to_old_normal", "Add to the old normal", "",
               "n = n_old + TBN (2c - 1) instead of TBN (2c - 1): "
               "the map's perturbation is halved and everything leans towards the flat normal."},
              p.addToOldNormal);
  v.boolParam({"no_renormalize", "Skip normalising", "",
               "Interpolated normals and tangents are shorter than 1 between "
               "vertices; unnormalised, the lighting dims and bands."},
              p.noRenormalize);
  v.boolParam({"no_orthogonalize", "Skip re-orthogonalising", "",
               "The interpolated tangent is no longer perpendicular "
               "to the interpolated normal; without Gram-Schmidt the frame is skewed."},
              p.noOrthogonalize);
  v.section("Light and view");
  v.floatParam({"light_elevation", "Light elevation", "deg",
                "Above the surface's plane (the wall's, or the horizon); "
                "low angles show relief best."},
               p.lightElevationDeg, -10.0f, 90.0f);
  v.floatParam({"light_azimuth", "Light azimuth", "deg", "Around the view axis of the wall."}, p.lightAzimuthDeg,
               -180.0f, 180.0f);
  v.enumParam(
      {"view", "View", "",
       "shaded; normals (world, 0.5 +- 0.5); tangent-angle (the tangent against "
       "compare_with's: 0 slate, half of angle_scale pink-red, angle_scale yellow; dimmed by the light); height; uv."},
      p.view, namesOf<kSurfaceViews>());
  v.intParam({"tessellation", "Sphere segments", "", "Segments of the brick sphere."}, p.tessellation, 8, 256);
}

// Per-vertex tangent frames are built only when something reads them: a technique that works in
// tangent space with a per-vertex source, the tangent-angle view, or the overlay.
bool SurfaceLab::needsTangents() const {
  const auto t = params.technique;
  const SurfaceChange changes = rowOf(kSurfaceTechniques, t).changes;
  const bool tangentSpace =
      changes == SurfaceChange::Normal || changes == SurfaceChange::Lookup ||
      (changes == SurfaceChange::Geometry && params.displacedNormals == DisplacedNormals::FromHeight);
  if (isDisplacing(t) && params.displacedNormals == DisplacedNormals::PerVertex)
    return true;  // read in the vertex stage
  const bool compared = params.view == SurfaceView::TangentAngle &&
                        (params.tangents != TangentSource::Screen || params.compareWith != TangentSource::Screen);
  return (tangentSpace && params.tangents != TangentSource::Screen) || compared || params.overlay;
}

SceneNeeds SurfaceLab::needs() const {
  SceneNeeds n;
  n.uvs = true;
  n.baseColorTextures = true;
  n.normalTextures = params.technique == SurfaceTechnique::NormalMap;
  n.heightTextures = usesHeight(params.technique) || params.view == SurfaceView::Height;
  n.heightConvention = params.heightMap;
  n.normalMapsAsSrgb = params.decoding == MapDecoding::Srgb;
  n.sampling.minFilter = rowOf(kTextureFilters, params.filter).minFilter;
  n.sampling.magFilter = rowOf(kTextureFilters, params.filter).magFilter;
  n.sampling.anisotropy = rowOf(kTextureFilters, params.filter).anisotropy;
  n.tessellation = params.tessellation;
  return n;
}

ProgramSpec SurfaceLab::programSpec(const SurfaceParams& p, bool hasUvs) const {
  ProgramSpec spec;
  SurfaceTechnique t = hasUvs ? p.technique : SurfaceTechnique::None;  // no UVs: nothing to map
  // Without tessellation stages (WebGL2) the mesh is split on the CPU as the
  // tessellator would split it, and the vertex stage displaces it as in displacement.
  if (t == SurfaceTechnique::Tessellation && !gl::hasTessellation()) t = SurfaceTechnique::Displacement;
  spec.name = "surface/" + std::string(rowOf(kSurfaceTechniques, t).name);
  const bool tess = t == SurfaceTechnique::Tessellation;
  spec.stages.push_back({GL_VERTEX_SHADER, "surface/surface.vert"});
  if (tess) {
    spec.stages.push_back({GL_TESS_CONTROL_SHADER, "surface/surface.tesc"});
    spec.stages.push_back({GL_TESS_EVALUATION_SHADER, "surface/surface.tese"});
    spec.defines.emplace_back("TESSELLATED", "1");
  }
  spec.stages.push_back({GL_FRAGMENT_SHADER, "surface/surface.frag"});
  auto define = [&](std::string_view name) { spec.defines.emplace_back(name, "1"); };
  if (const std::string_view own = rowOf(kSurfaceTechniques, t).define; !own.empty()) define(own);
  if (t == SurfaceTechnique::Bump && p.bumpForm == BumpForm::Games101) define("BUMP_GAMES101");
  // The tessellated surface's vertices are made in the evaluation stage, which takes no tangents:
  // per-vertex normals there are the height field's per pixel.
  const bool perVertex = p.displacedNormals == DisplacedNormals::PerVertex && !tess;
  const bool fromHeight =
      p.displacedNormals == DisplacedNormals::FromHeight || (p.displacedNormals == DisplacedNormals::PerVertex && tess);
  if (isDisplacing(t) && fromHeight) define("HEIGHT_NORMALS");
  if (isDisplacing(t) && perVertex) define("VERTEX_NORMALS");
  if (isParallax(t) && p.selfShadow) define("SELF_SHADOW");
  if (t == SurfaceTechnique::Truth && p.selfShadow) define("TRUE_SHADOW");
  if (p.tangents == TangentSource::Screen) define("TANGENTS_SCREEN");
  if (p.compareWith == TangentSource::Screen) define("COMPARE_SCREEN");
  if (p.addToOldNormal) define("WRONG_ADD_TO_NORMAL");
  if (p.noRenormalize) define("WRONG_NO_RENORMALIZE");
  if (p.noOrthogonalize) define("WRONG_NO_ORTHOGONALIZE");
  define(rowOf(kSurfaceViews, p.view).define);
  return spec;
}

ProgramSpec SurfaceLab::overlaySpec() {
  return {"surface/tbn overlay",
          {{GL_VERTEX_SHADER, "surface/tbn.vert"},
           {GL_GEOMETRY_SHADER, "surface/tbn.geom"},
           {GL_FRAGMENT_SHADER, "surface/tbn.frag"}},
          {}};
}

// Per technique, a pairwise cover of the other choices the shaders are compiled for: every value,
// and every pair of values, of view, tangent source and comparison, GAMES101's bump form, displaced
// normals, self-shadowing and the three wrong steps in some program of that technique (a
// technique's own defines appear with everything else; gl/lab_lifecycle_test.cpp draws random
// settings against it).
std::vector<ProgramSpec> SurfaceLab::allPrograms() const {
  std::vector<ProgramSpec> all = {overlaySpec()};
  for (int t = 0; t < int(SurfaceTechnique::Count); ++t)
    for (const auto& row :
         pairwiseCover({int(SurfaceView::Count), 3, 3, 2, int(std::size(kDisplacedNormals)), 2, 2, 2, 2})) {
      SurfaceParams p;
      p.technique = SurfaceTechnique(t);
      p.view = SurfaceView(row[0]);
      p.tangents = TangentSource(row[1]);
      p.compareWith = TangentSource(row[2]);
      p.bumpForm = BumpForm(row[3]);
      p.displacedNormals = DisplacedNormals(row[4]);
      p.selfShadow = row[5] == 1;
      p.addToOldNormal = row[6] == 1;
      p.noRenormalize = row[7] == 1;
      p.noOrthogonalize = row[8] == 1;
      all.push_back(programSpec(p, true));
    }
  // One of each: rows that differ only in what this technique ignores compile the same program.
  std::set<std::string> seen;
  std::erase_if(all, [&](const ProgramSpec& spec) { return !seen.insert(spec.key()).second; });
  return all;
}

std::string SurfaceLab::setup(LabContext& ctx) {
  shaders_ = &ctx.shaders;
  const uint8_t white[4] = {255, 255, 255, 255}, flat[4] = {128, 128, 255, 255}, top[4] = {255, 255, 255, 255};
  whiteMap_ = onePixel(white);
  flatNormalMap_ = onePixel(flat);
  topHeightMap_ = onePixel(top);
  heightSampler_ = gl::Sampler::make();
  glSamplerParameteri(heightSampler_.get(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glSamplerParameteri(heightSampler_.get(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glSamplerParameteri(heightSampler_.get(), GL_TEXTURE_WRAP_S, GL_REPEAT);
  glSamplerParameteri(heightSampler_.get(), GL_TEXTURE_WRAP_T, GL_REPEAT);
  return {};
}

int SurfaceLab::levelFor(const Scene& scene) const {
  int level = 0;
  if (params.technique == SurfaceTechnique::Displacement) level = params.subdivision;
  if (params.technique == SurfaceTechnique::Truth) {
    // About one vertex per texel of the height map, wherever the scene has one.
    int texels = 256;
    for (auto& mat : scene.materials)
      if (mat.heightImage >= 0) texels = std::max(texels, scene.images[size_t(mat.heightImage)].size.x);
    for (auto& inst : scene.instances)
      level = std::max(level, levelsForTexelSize(scene.meshes[size_t(inst.mesh)], texels, 10));
  }
  size_t triangles = scene.triangleCount();
  int allowed = 0;
  while (allowed < level && triangles * 4 <= size_t(kMaxTriangles)) {
    triangles *= 4;
    ++allowed;
  }
  return allowed;
}

// Tessellation makes level^2 triangles of every patch: held to the subdivision's triangle cap,
// or the brick sphere's 65,536 patches at level 64 would be a quarter of a billion triangles a frame.
int SurfaceLab::tessLevelFor(const Scene& scene) {
  int tessLevel = params.tessLevel;
  size_t patches = 0;
  for (const Instance& inst : scene.instances)
    if (const MeshData& m = scene.meshes[size_t(inst.mesh)]; !m.uvs.empty()) patches += m.triangleCount();
  while (tessLevel > 1 && patches * size_t(tessLevel) * size_t(tessLevel) > size_t(kMaxTriangles)) --tessLevel;
  if (tessLevel < params.tessLevel)
    frameNotes_.push_back("tessellation level " + std::to_string(params.tessLevel) + " on " + std::to_string(patches) +
                          " patches would make " +
                          std::to_string(patches * size_t(params.tessLevel) * size_t(params.tessLevel)) +
                          " triangles; drawn at level " + std::to_string(tessLevel) + " (at most " +
                          std::to_string(kMaxTriangles) + ", as subdivision)");
  if (!gl::hasTessellation())
    frameNotes_.push_back("this context has no tessellation stages (WebGL2 has none): each triangle is cut into " +
                          std::to_string(tessLevel * tessLevel) +
                          " on the CPU (a regular grid with the tessellator's "
                          "edge points) and displaced in the vertex stage");
  return tessLevel;
}

// The UVs' shear over the scene, once per scene build (the tangents panel's figures).
void SurfaceLab::measureUvShear(const Scene& scene) {
  if (shearRevision_ == scene.revision) return;
  std::vector<float> shear;
  for (const MeshData& m : scene.meshes) {
    const std::vector<float> s = uvShearDegrees(m);
    shear.insert(shear.end(), s.begin(), s.end());
  }
  std::sort(shear.begin(), shear.end());
  shearMedian_ = shear.empty() ? 0.0f : shear[shear.size() / 2];
  shearP90_ = shear.empty() ? 0.0f : shear[shear.size() * 9 / 10];
  shearRevision_ = scene.revision;
}

// The first drawn material with UVs but no height map, and the note when the technique reads one.
void SurfaceLab::noteHeightless(const Frame& frame, std::span<const SurfaceDraw> draws) {
  heightless_.clear();
  for (const SurfaceDraw& d : draws) {
    const Material& mat = frame.scene.materials[size_t(d.material)];
    if (d.hasUvs && heightless_.empty() &&
        (mat.heightImage < 0 || (needs().heightTextures && !frame.gpu.heightTexture(mat))))
      heightless_ = mat.name;
  }
  if (!heightless_.empty() && (usesHeight(params.technique) || params.view == SurfaceView::Height))
    frameNotes_.push_back("material '" + heightless_ +
                          "' has no height map: " + std::string(rowOf(kSurfaceTechniques, params.technique).name) +
                          " has nothing to read and draws it flat; give its MTL a disp map (height_map = depth for "
                          "LearnOpenGL's depth maps), or drop a height image on the window");
}

void SurfaceLab::render(Frame& frame) {
  frameNotes_.clear();
  glEnable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glClearColor(0.02f, 0.02f, 0.025f, 0.0f);  // alpha 0: background, for the silhouette metric
  if (frame.slice == 0) glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  const bool tessellating = params.technique == SurfaceTechnique::Tessellation;
  const bool tess = tessellating && gl::hasTessellation();
  const int tessLevel = tessellating ? tessLevelFor(frame.scene) : params.tessLevel;
  SurfaceGeometryKey key;
  key.revision = frame.scene.revision;
  key.level = levelFor(frame.scene);
  key.parts = tessellating && !tess ? tessLevel : 1;
  key.tangents = needsTangents();
  if (key.tangents) {  // otherwise the sources do not matter: one key, one build
    key.source = params.tangents;
    key.compare = params.compareWith;
  }
  const auto& draws = geometry_.get(frame.scene, key, frameNotes_);
  measureUvShear(frame.scene);
  drawnLevel_ = key.level;
  drawnTriangles_ = 0;
  noteHeightless(frame, draws);
  std::string what = std::string(rowOf(kSurfaceTechniques, params.technique).name);
  if (params.technique == SurfaceTechnique::Displacement || params.technique == SurfaceTechnique::Truth)
    what += ", subdivision " + std::to_string(key.level);
  if (tessellating) what += ", level " + std::to_string(tessLevel) + (tess ? "" : " (cut on the CPU)");
  {
    auto pass = frame.pass("surface: " + what);
    // The light: elevation above the wall's plane (its normal is +z) or the ground's (+y).
    const float el = glm::radians(params.lightElevationDeg), az = glm::radians(params.lightAzimuthDeg);
    const bool wall = frame.scene.name == "bricks" || frame.scene.name == "bricks-learnopengl";
    const glm::vec3 lightDir = wall ? glm::vec3(std::cos(el) * std::sin(az), std::cos(el) * std::cos(az), std::sin(el))
                                    : glm::vec3(std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az));
    for (const SurfaceDraw& d : draws) drawSurface(frame, d, tess ? tessLevel : 0, glm::normalize(lightDir));
  }
  if (params.overlay && frame.slice + 1 == frame.slices) {
    auto pass = frame.pass("tangent frames");
    drawTangentFrames(frame, key);
  }
}

// One draw of the surface; `tessLevel` 0 without tessellation stages.
void SurfaceLab::drawSurface(Frame& frame, const SurfaceDraw& d, int tessLevel, glm::vec3 lightDir) {
  static const std::string noUvs =
      "a mesh has no UVs: there is nothing to look the maps up with, so it is "
      "drawn with its own normals and no surface detail";
  if (!d.hasUvs && params.technique != SurfaceTechnique::None &&
      std::find(frameNotes_.begin(), frameNotes_.end(), noUvs) == frameNotes_.end())
    frameNotes_.push_back(noUvs);
  const Material& mat = frame.scene.materials[size_t(d.material)];
  Program& prog = program_.get(*shaders_, programSpec(params, d.hasUvs));
  prog.use();
  prog.set("u_model", d.model);
  prog.set("u_normalMatrix", glm::mat3(glm::inverseTranspose(d.model)));
  prog.set("u_viewProj", frame.viewProj());
  prog.set("u_eye", frame.camera.eye());
  prog.set("u_lightDir", lightDir);
  prog.set("u_baseColor", mat.baseColor);
  const gl::Texture2D* color = frame.gpu.baseColorTexture(mat);
  const gl::Texture2D* normal = frame.gpu.normalTexture(mat);
  const gl::Texture2D* height = frame.gpu.heightTexture(mat);
  (color ? *color : whiteMap_).bind(kColorUnit);
  (normal ? *normal : flatNormalMap_).bind(kNormalUnit);
  (height ? *height : topHeightMap_).bind(kHeightUnit);
  glBindSampler(kHeightUnit, heightSampler_.get());
  prog.set("u_baseColorMap", int(kColorUnit));
  prog.set("u_normalMap", int(kNormalUnit));
  prog.set("u_heightMap", int(kHeightUnit));
  const glm::ivec2 hs = height ? height->size() : glm::ivec2(1);
  prog.set("u_heightTexel", 1.0f / glm::vec2(hs));
  prog.set("u_heightScale", params.heightScale);
  prog.set("u_heightBase", params.surfaceAt == SurfaceAt::Top ? 1.0f : 0.0f);
  prog.set("u_normalStrength", params.normalStrength);
  prog.set("u_greenSign", params.green == GreenConvention::OpenGl ? 1.0f : -1.0f);
  prog.set("u_kh", params.kh);
  prog.set("u_kn", params.kn);
  prog.set("u_layers", params.layers);
  // A mesh without UVs gets the plain program (programSpec): patches only where tessellation stages are.
  const bool patches = tessLevel > 0 && d.hasUvs;
  if (patches) prog.set("u_tessLevel", float(tessLevel));  // surface.tesc's
  prog.set("u_angleScale", params.angleScale);
  // A sliced frame (a truth drawn in parts) draws its share of the triangles.
  const size_t first = d.triangles * size_t(frame.slice) / size_t(frame.slices);
  const size_t last = d.triangles * size_t(frame.slice + 1) / size_t(frame.slices);
  d.mesh.drawTriangles(patches ? Primitive::Patches : Primitive::Triangles, first, last - first);
  glBindSampler(kHeightUnit, 0);
  drawnTriangles_ += patches ? d.triangles * size_t(tessLevel) * size_t(tessLevel) : d.triangles;
}

// Each vertex's tangent frame as three short lines, on the unsubdivided mesh.
void SurfaceLab::drawTangentFrames(Frame& frame, SurfaceGeometryKey key) {
  const Bounds b = frame.scene.bounds;
  Program& prog = overlay_.get(*shaders_, overlaySpec());
  prog.use();
  prog.set("u_viewProj", frame.viewProj());
  SurfaceGeometryKey base = key;
  base.level = 0;
  base.tangents = true;
  for (const SurfaceDraw& d : geometry_.get(frame.scene, base, frameNotes_)) {
    // Half an edge keeps neighbouring frames apart on a dense mesh; a few percent of the scene on a coarse one.
    const float scale = glm::length(glm::vec3(d.model[0]));
    prog.set("u_length", params.overlayLength * std::min(0.04f * b.radius(), 0.5f * d.meanEdge * scale));
    prog.set("u_model", d.model);
    prog.set("u_normalMatrix", glm::mat3(glm::inverseTranspose(d.model)));
    d.mesh.draw(Primitive::Points);
  }
}

std::vector<ProgramRef> SurfaceLab::activePrograms() const {
  std::vector<ProgramRef> out;
  if (program_.current()) out.push_back(program_.current());
  if (params.overlay && overlay_.current()) out.push_back(overlay_.current());
  return out;
}

}  // namespace shadelab

#include "labs/shadows/shadows_lab.h"

#include <glm/gtc/matrix_inverse.hpp>

#include "labs/shadows/ray_visibility.h"

namespace shadelab {
namespace {

constexpr std::string_view kLightTypes[] = {"directional", "spot", "point"};
constexpr std::string_view kFilters[] = {"hard", "hardware-pcf", "pcf", "poisson", "pcss"};
constexpr std::string_view kViews[] = {"shaded", "visibility", "bias-heat", "texel-density",
                                       "pcss-blocker", "pcss-penumbra", "depth-raw", "depth-linear"};
constexpr std::string_view kFormats[] = {"16", "24", "32f"};
constexpr std::string_view kMapSizes[] = {"256", "512", "1024", "2048", "4096", "8192"};
constexpr std::string_view kSampleCounts[] = {"8", "16", "32", "64"};
constexpr std::string_view kDepthLights[] = {"key", "fill"};
const GLenum kFormatEnums[] = {GL_DEPTH_COMPONENT16, GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT32F};

// Texture units of lit.frag's samplers, fixed so no two sampler types ever share a unit.
enum Unit { kKeyMap = 0, kKeyCube, kKeyCmp, kKeyCmpCube, kFillMap, kFillCmp, kNoCube, kNoCmpCube };
enum Slot { kLitSlot = 0, kKeyDepthSlot, kFillDepthSlot, kDepthViewSlot, kLinesSlot, kSlotCount };

bool viewIsDepthMap(ShadowView v) { return v == ShadowView::DepthRaw || v == ShadowView::DepthLinear; }

}  // namespace

ShadowsLab::ShadowsLab() = default;
ShadowsLab::~ShadowsLab() = default;

std::string_view ShadowsLab::summary() const {
  return "A shadow map stores, per texel, the depth of the nearest surface seen from the light; a pixel is in "
         "shadow when it lies farther than that. Walk the path: set bias to 0 (acne), raise it (peter-panning), "
         "turn off border clamp and the far fix (the artifacts they remove), then PCF, Poisson and PCSS. "
         "Every step is measured against ray-traced visibility.";
}

void ShadowsLab::visitParams(ParamVisitor& v) {
  auto& p = params;
  v.section("Key light");
  v.enumParam({"light_type", "Key light", "", "directional: orthographic map; spot: perspective map; point: a cube "
               "map drawn in one pass (geometry shader writes gl_Layer)."}, p.keyType, kLightTypes);
  v.boolParam({"key_casts", "Key casts shadows", "", "Off: no depth pass runs for the key light."}, p.keyCasts);
  v.floatParam({"light_elevation", "Light elevation", "deg", "Key light above the horizon; 85..89.9 from zenith is "
                "grazing (elevation 5..0.1)."}, p.elevationDeg, 0.1f, 90.0f);
  v.floatParam({"light_azimuth", "Light azimuth", "deg", "Key light around the vertical axis."}, p.azimuthDeg, -180.0f, 180.0f);
  v.floatParam({"light_distance", "Light distance", "radii", "Spot/point light distance from the scene centre, in "
                "scene radii (below 1 the light is inside the scene)."}, p.lightDistance, 0.0f, 20.0f);
  v.floatParam({"spot_angle", "Spot angle", "deg", "Full cone angle of the spot light (and its map's field of view)."},
               p.spotAngleDeg, 5.0f, 160.0f);
  v.floatParam({"light_radius", "Light radius", "radii", "Area light radius in scene radii, for PCSS and its "
                "reference; 0 = a point light, hard shadows. Directional: seen from 3 radii away."},
               p.lightRadius, 0.0f, 10.0f);
  v.section("Fill light");
  v.boolParam({"fill_light", "Fill light", "", "A second light (a spot) with its own shadow map."}, p.fillLight);
  v.boolParam({"fill_casts", "Fill casts shadows", "", "Off: the fill light lights, but no depth pass runs for it."}, p.fillCasts);
  v.section("Shadow map");
  v.choiceParam({"map_size", "Map size", "texels", "Shadow map resolution (per cube face for a point light)."},
                p.mapSizeIndex, kMapSizes);
  v.enumParam({"depth_format", "Depth format", "bits", "16, 24-bit fixed point or 32-bit float depth."}, p.depthFormat, kFormats);
  v.boolParam({"auto_fit", "Auto-fit frustum", "", "Fit the light's extent and near/far to the scene bounds."}, p.autoFit);
  v.floatParam({"ortho_extent", "Ortho extent", "radii", "Directional light box half-width when auto-fit is off."},
               p.orthoExtent, 1e-3f, 1e3f, true);
  v.floatParam({"near", "Light near", "radii", "Light near plane when auto-fit is off."}, p.nearPlane, 1e-6f, 1e3f, true);
  v.floatParam({"far", "Light far", "radii", "Light far plane when auto-fit is off."}, p.farPlane, 1e-3f, 1e4f, true);
  v.boolParam({"border_clamp", "Border clamp", "", "Outside the map reads depth 1 (lit). Off: CLAMP_TO_EDGE repeats "
               "edge texels, stretching shadows past the map."}, p.borderClamp);
  v.boolParam({"far_fix", "Far-plane fix", "", "Receivers beyond the light's far plane are lit. Off: they compare as "
               "shadowed."}, p.farFix);
  v.boolParam({"cull_front", "Cull front faces", "", "Depth pass draws back faces: closed meshes lose acne, thin "
               "ones leak."}, p.cullFront);
  v.boolParam({"six_cube_passes", "Cube map in six passes", "", "Point light: draw the six faces in six passes "
               "instead of one geometry-shader pass (compare their cost)."}, p.sixCubePasses);
  v.section("Bias");
  v.floatParam({"bias", "Constant bias", "texels", "Depth bias floor, in shadow-map texels at the receiver."},
               p.bias, 0.0f, 50.0f);
  v.floatParam({"slope_bias", "Slope bias k", "texels", "bias = max(k (1 - N.L), constant): more where the light "
                "grazes."}, p.slopeBias, 0.0f, 50.0f);
  v.floatParam({"normal_offset", "Normal offset", "texels", "Move the lookup point along the normal before "
                "projecting."}, p.normalOffset, 0.0f, 20.0f);
  v.floatParam({"offset_factor", "Polygon offset factor", "", "glPolygonOffset factor in the depth pass (slope)."},
               p.offsetFactor, 0.0f, 20.0f);
  v.floatParam({"offset_units", "Polygon offset units", "", "glPolygonOffset units in the depth pass (constant)."},
               p.offsetUnits, 0.0f, 10000.0f);
  v.boolParam({"receiver_plane", "Receiver-plane depth", "", "Each filter tap compares against the receiver's plane "
               "at that tap, not the centre depth: wide kernels on slopes need no extra bias."}, p.receiverPlane);
  v.section("Filter");
  v.enumParam({"filter", "Filter", "", "hard: one tap; hardware-pcf: sampler2DShadow, 2x2 bilinear; pcf: N x N taps; "
               "poisson: a Poisson disk; pcss: blocker search + penumbra-sized PCF."}, p.filter, kFilters);
  v.intParam({"pcf_size", "PCF kernel N", "taps", "N x N taps; a compile-time loop bound (one program per N)."},
             p.pcfSize, 1, 15);
  v.choiceParam({"poisson_samples", "Poisson samples", "", "Taps of the Poisson-disk filter."}, p.poissonIndex, kSampleCounts);
  v.floatParam({"filter_radius", "Poisson radius", "texels", "Radius of the Poisson-disk filter."}, p.filterRadius, 0.0f, 32.0f);
  v.boolParam({"rotate", "Rotate per pixel", "", "Rotate the Poisson disk per pixel: banding becomes noise."}, p.rotateSamples);
  v.choiceParam({"blocker_samples", "PCSS blocker samples", "", "Taps of the blocker search."}, p.blockerIndex, kSampleCounts);
  v.choiceParam({"pcss_samples", "PCSS filter samples", "", "Taps of the penumbra filter."}, p.pcssIndex, kSampleCounts);
  v.section("View");
  v.enumParam({"view", "View", "", "shaded; visibility (the key light's shadow term); bias-heat (receiver - occluder - "
               "bias: red = acne, blue = leaks); texel-density; pcss-blocker; pcss-penumbra; depth-raw/-linear (the "
               "key map; a cube unrolled)."}, p.view, kViews);
  v.choiceParam({"depth_light", "Depth view of", "", "Which light's map the depth views show."}, p.depthLight, kDepthLights);
  v.floatParam({"depth_zoom", "Depth view zoom", "x", "Magnification of the depth views."}, p.depthZoom, 1.0f, 64.0f, true);
  v.floatParam({"depth_centre_u", "Depth view centre u", "", "Map coordinate at the middle of the view."},
               p.depthCentreU, 0.0f, 1.0f);
  v.floatParam({"depth_centre_v", "Depth view centre v", "", "Map coordinate at the middle of the view."},
               p.depthCentreV, 0.0f, 1.0f);
  v.boolParam({"show_frustum", "Show light frustum", "", "Draw the key light's frustum (directional, spot)."}, p.showFrustum);
  v.section("Scene");
  v.intParam({"tessellation", "Tessellation", "segments", "Segments of procedural spheres and tori."}, p.tessellation, 3, 256);
  v.floatParam({"scene_scale", "Scene scale", "", "Uniform scale of the whole scene (1e-3 .. 1e4); lengths in "
                "radii and texels follow it."}, p.sceneScale, 1e-3f, 1e4f, true);
}

SceneNeeds ShadowsLab::needs() const {
  SceneNeeds n;
  n.tessellation = params.tessellation;
  n.scale = params.sceneScale;
  return n;
}

LightSetup ShadowsLab::keySetup() const {
  LightSetup s;
  s.type = params.keyType;
  s.azimuthDeg = params.azimuthDeg;
  s.elevationDeg = params.elevationDeg;
  s.distance = params.lightDistance;
  s.spotAngleDeg = params.spotAngleDeg;
  s.radius = params.lightRadius;
  s.autoFit = params.autoFit;
  s.orthoExtent = params.orthoExtent;
  s.nearPlane = params.nearPlane;
  s.farPlane = params.farPlane;
  return s;
}

LightSetup ShadowsLab::fillSetup() const {
  LightSetup s;
  s.type = LightType::Spot;
  s.azimuthDeg = params.azimuthDeg + 150.0f;
  s.elevationDeg = 35.0f;
  s.distance = 3.0f;
  s.spotAngleDeg = 60.0f;
  return s;
}

ProgramSpec ShadowsLab::litSpec(const ShadowsParams& p, InternalView internal) const {
  ProgramSpec spec;
  spec.stages = {{GL_VERTEX_SHADER, "shadows/lit.vert"}, {GL_FRAGMENT_SHADER, "shadows/lit.frag"}};
  spec.defines.emplace_back("KEY_TYPE", std::to_string(int(p.keyType)));
  const bool gbuffer = internal != InternalView::None;
  if (p.keyCasts && !gbuffer) spec.defines.emplace_back("KEY_CASTS", "1");
  if (p.fillLight && !gbuffer) {
    spec.defines.emplace_back("FILL_LIGHT", "1");
    if (p.fillCasts) spec.defines.emplace_back("FILL_CASTS", "1");
  }
  if (p.farFix) spec.defines.emplace_back("FAR_FIX", "1");
  if (p.receiverPlane) spec.defines.emplace_back("RECEIVER_PLANE", "1");
  static const char* filterDefine[] = {"FILTER_HARD", "FILTER_HW_PCF", "FILTER_PCF", "FILTER_POISSON", "FILTER_PCSS"};
  spec.defines.emplace_back(filterDefine[int(p.filter)], "1");
  if (p.filter == ShadowFilter::Pcf) spec.defines.emplace_back("PCF_SIZE", std::to_string(p.pcfSize));
  if (p.filter == ShadowFilter::Poisson) {
    spec.defines.emplace_back("POISSON_COUNT", std::to_string(8 << p.poissonIndex));
    if (p.rotateSamples) spec.defines.emplace_back("ROTATE_SAMPLES", "1");
  }
  if (p.filter == ShadowFilter::Pcss) {
    spec.defines.emplace_back("BLOCKER_COUNT", std::to_string(8 << p.blockerIndex));
    spec.defines.emplace_back("PCSS_COUNT", std::to_string(8 << p.pcssIndex));
  }
  static const char* viewDefine[] = {"VIEW_SHADED", "VIEW_VISIBILITY", "VIEW_BIAS_HEAT", "VIEW_TEXEL_DENSITY",
                                     "VIEW_PCSS_BLOCKER", "VIEW_PCSS_PENUMBRA", "VIEW_SHADED", "VIEW_SHADED"};
  spec.defines.emplace_back(internal == InternalView::Position ? "VIEW_POSITION"
                            : internal == InternalView::Normal ? "VIEW_NORMAL"
                                                               : viewDefine[int(p.view)], "1");
  spec.name = "shadows/lit " + std::string(kLightTypes[int(p.keyType)]) + " " + std::string(kFilters[int(p.filter)]);
  return spec;
}

ProgramSpec ShadowsLab::depthSpec(bool cube, bool sixPasses) const {
  ProgramSpec spec;
  const bool oneCubePass = cube && !sixPasses;
  spec.name = oneCubePass ? "shadows/depth cube" : cube ? "shadows/depth cube face" : "shadows/depth";
  spec.stages.push_back({GL_VERTEX_SHADER, "shadows/depth.vert"});
  if (oneCubePass) spec.stages.push_back({GL_GEOMETRY_SHADER, "shadows/depth_cube.geom"});
  spec.stages.push_back({GL_FRAGMENT_SHADER, "shadows/depth.frag"});
  if (cube) spec.defines.emplace_back(oneCubePass ? "CUBE_MAP" : "CUBE_FACE", "1");
  return spec;
}

ProgramSpec ShadowsLab::linesSpec() {
  ProgramSpec spec;
  spec.name = "shadows/lines";
  spec.stages = {{GL_VERTEX_SHADER, "shadows/lines.vert"}, {GL_FRAGMENT_SHADER, "shadows/lines.frag"}};
  return spec;
}

ProgramSpec ShadowsLab::depthViewSpec(const ShadowsParams& p) const {
  ProgramSpec spec;
  spec.name = "shadows/depth view";
  spec.stages = {{GL_VERTEX_SHADER, "shadows/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "shadows/depth_view.frag"}};
  const LightType shown = p.depthLight == 1 ? LightType::Spot : p.keyType;  // the fill light is a spot
  spec.defines.emplace_back("KEY_TYPE", std::to_string(int(shown)));
  if (p.view == ShadowView::DepthLinear) spec.defines.emplace_back("LINEAR_DEPTH", "1");
  return spec;
}

std::vector<ProgramSpec> ShadowsLab::allPrograms() const {
  std::vector<ProgramSpec> all = {depthSpec(false, false), depthSpec(true, false), depthSpec(true, true), linesSpec()};
  ShadowsParams p;
  for (int type = 0; type < 3; ++type) {
    p.keyType = LightType(type);
    for (int view : {6, 7}) {
      p.view = ShadowView(view);
      all.push_back(depthViewSpec(p));
    }
    p.depthLight = 1;
    all.push_back(depthViewSpec(p));
    p.depthLight = 0;
    for (int view = 0; view < 6; ++view)
      for (int filter = 0; filter < 5; ++filter) {
        p.view = ShadowView(view);
        p.filter = ShadowFilter(filter);
        p.fillLight = view == 0 && filter == 2;
        p.pcfSize = 1 + 2 * (type + view) % 15;
        p.poissonIndex = view % 4;
        p.rotateSamples = view % 2 == 0;
        p.farFix = view != 1;
        p.receiverPlane = filter % 2 == 0;
        all.push_back(litSpec(p, InternalView::None));
      }
    all.push_back(litSpec(p, InternalView::Position));
    all.push_back(litSpec(p, InternalView::Normal));
  }
  p = ShadowsParams{};
  for (int n = 1; n <= 15; ++n) {  // every PCF kernel size is its own program
    p.pcfSize = n;
    all.push_back(litSpec(p, InternalView::None));
  }
  return all;
}

std::string ShadowsLab::setup(LabContext& ctx) {
  shaders_ = &ctx.shaders;
  programs_.assign(kSlotCount, ProgramSlot{});
  dummies_.create();
  emptyVao_ = gl::VertexArray::make();
  // The 12 edges of the NDC cube, drawn through the light's inverse view-projection.
  const glm::vec3 c[8] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}};
  const int edges[24] = {0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 5, 6, 6, 7, 7, 4, 0, 4, 1, 5, 2, 6, 3, 7};
  std::vector<glm::vec3> lines;
  for (int e : edges) lines.push_back(c[e]);
  frustumVao_ = gl::VertexArray::make();
  frustumVbo_ = gl::Buffer::make();
  glBindVertexArray(frustumVao_.get());
  glBindBuffer(GL_ARRAY_BUFFER, frustumVbo_.get());
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(lines.size() * sizeof(glm::vec3)), lines.data(), GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
  glBindVertexArray(0);
  poisson_ = poissonDisk(64);
  return {};
}

void ShadowsLab::teardown() {
  programs_.clear();
  keyMap_.release();
  fillMap_.release();
  dummies_.release();
  emptyVao_.reset();
  frustumVao_.reset();
  frustumVbo_.reset();
  rayScene_.reset();
  rayRevision_ = -1;
  shaders_ = nullptr;
}

std::vector<ProgramRef> ShadowsLab::activePrograms() const {
  std::vector<ProgramRef> out;
  for (auto& slot : programs_)
    if (slot.current()) out.push_back(slot.current());
  return out;
}

static void setLight(Program& prog, const char* name, const LightFrame& L, int mapSize) {
  const std::string n(name);
  prog.set((n + ".viewProj").c_str(), L.viewProj);
  prog.set((n + ".position").c_str(), L.position);
  prog.set((n + ".axis").c_str(), L.direction);
  prog.set((n + ".right").c_str(), glm::vec3(L.view[0][0], L.view[1][0], L.view[2][0]));
  prog.set((n + ".up").c_str(), glm::vec3(L.view[0][1], L.view[1][1], L.view[2][1]));
  prog.set((n + ".nearPlane").c_str(), L.nearPlane);
  prog.set((n + ".farPlane").c_str(), L.farPlane);
  prog.set((n + ".halfWidth").c_str(), L.type == LightType::Directional ? L.orthoHalfExtent : L.tanHalfFov);
  prog.set((n + ".mapSize").c_str(), float(mapSize));
  prog.set((n + ".radius").c_str(), L.radiusWorld);
}

void ShadowsLab::drawLit(Frame& frame, Program& prog, const LightFrame& key, const LightFrame* fill) {
  const Bounds b = frame.scene.bounds;
  prog.use();
  prog.set("u_viewProj", frame.viewProj());
  prog.set("u_eye", frame.camera.eye());
  prog.set("u_ambient", 0.12f);
  setLight(prog, "u_key", key, params.mapSize());
  // Irradiance 1 at the scene centre whatever the light type and scale.
  const float keyR2 = key.type == LightType::Directional ? 1.0f : glm::dot(key.position - b.center(), key.position - b.center());
  prog.set("u_keyPower", glm::vec3(1.0f, 0.97f, 0.92f) * keyR2);
  prog.set("u_bias", params.bias);
  prog.set("u_slopeBias", params.slopeBias);
  prog.set("u_normalOffset", params.normalOffset);
  prog.set("u_filterRadius", params.filterRadius);
  prog.setArray("u_poisson", poisson_.data(), int(poisson_.size()));
  const struct { const char* name; int unit; } units[] = {{"u_keyMap", kKeyMap}, {"u_keyCube", kKeyCube}, {"u_keyCmp", kKeyCmp},
      {"u_keyCmpCube", kKeyCmpCube}, {"u_fillMap", kFillMap}, {"u_fillCmp", kFillCmp}, {"u_noCube", kNoCube},
      {"u_noCmpCube", kNoCmpCube}};
  for (auto& u : units) prog.set(u.name, u.unit);
  // Every unit gets a texture of its sampler's type; the real maps replace the dummies.
  for (int unit : {kKeyMap, kKeyCmp, kFillMap, kFillCmp}) dummies_.bind2D(unit);
  for (int unit : {kKeyCube, kKeyCmpCube, kNoCube, kNoCmpCube}) dummies_.bindCube(unit);
  if (keyMap_ && params.keyCasts) {
    if (keyMap_.cube()) keyMap_.bind(kKeyCube, kKeyCmpCube, params.borderClamp);
    else keyMap_.bind(kKeyMap, kKeyCmp, params.borderClamp);
  }
  if (fill) {
    setLight(prog, "u_fill", *fill, params.mapSize());
    const float r2 = glm::dot(fill->position - b.center(), fill->position - b.center());
    prog.set("u_fillPower", glm::vec3(0.35f, 0.45f, 0.6f) * r2);
    if (fillMap_ && params.fillCasts) fillMap_.bind(kFillMap, kFillCmp, params.borderClamp);
  }
  for (const Instance& inst : frame.scene.instances) {
    const Material& mat = frame.scene.materials[size_t(frame.scene.meshes[size_t(inst.mesh)].material)];
    prog.set("u_model", inst.model);
    prog.set("u_normalMatrix", glm::mat3(glm::inverseTranspose(inst.model)));
    prog.set("u_baseColor", mat.baseColor);
    frame.gpu.draw(inst);
  }
  for (int unit = 0; unit <= kNoCmpCube; ++unit) glBindSampler(unit, 0);
}

void ShadowsLab::drawFrustum(Frame& frame, const LightFrame& key) {
  if (key.type == LightType::Point) return;
  auto pass = frame.pass("light frustum");
  Program& prog = fetch(kLinesSlot, linesSpec());
  prog.use();
  prog.set("u_viewProj", frame.viewProj());
  prog.set("u_lightInverse", glm::inverse(key.viewProj));
  prog.set("u_color", glm::vec3(1.0f, 0.85f, 0.2f));
  glBindVertexArray(frustumVao_.get());
  glDrawArrays(GL_LINES, 0, 24);
}

void ShadowsLab::render(Frame& frame) {
  const Bounds bounds = frame.scene.bounds;
  lightWarnings_.clear();
  const LightFrame key = buildLight(keySetup(), bounds, lightWarnings_);
  std::vector<std::string> ignored;
  const LightFrame fill = buildLight(fillSetup(), bounds, ignored);
  const GLenum format = kFormatEnums[int(params.depthFormat)];
  const DepthPassState depthState{params.cullFront, params.offsetFactor, params.offsetUnits, params.sixCubePasses};
  const bool gbuffer = internalView_ != InternalView::None;
  const std::string mapName = std::to_string(params.mapSize()) + "^2 D" + std::string(kFormats[int(params.depthFormat)]);

  // 1. Depth passes, only for lights that cast and only when the view reads their maps.
  if (params.keyCasts && !gbuffer) {
    const bool cube = params.keyType == LightType::Point;
    auto pass = frame.pass("shadow map: key " + std::string(kLightTypes[int(params.keyType)]) + " " + mapName +
                           (cube ? (params.sixCubePasses ? " x6 (6 passes)" : " x6 (1 pass)") : ""));
    keyMap_.ensure(cube, params.mapSize(), format);
    keyMap_.render(frame.scene, frame.gpu, fetch(kKeyDepthSlot, depthSpec(cube, params.sixCubePasses)), key, depthState);
  } else if (!params.keyCasts) {
    keyMap_.release();  // (a g-buffer render keeps it: the next frame needs it again)
  }
  const bool fillMapNeeded = params.fillLight && params.fillCasts && !gbuffer &&
                             (!viewIsDepthMap(params.view) || params.depthLight == 1);
  if (fillMapNeeded) {
    auto pass = frame.pass("shadow map: fill spot " + mapName);
    fillMap_.ensure(false, params.mapSize(), format);
    fillMap_.render(frame.scene, frame.gpu, fetch(kFillDepthSlot, depthSpec(false, false)), fill, depthState);
  } else if (!(params.fillLight && params.fillCasts)) {
    fillMap_.release();
  }

  // 2. The camera pass: the lit scene (or a diagnostic view of it), or the key map itself.
  frame.target.bind();
  glDisable(GL_CULL_FACE);
  glEnable(GL_DEPTH_TEST);
  glClearColor(0.02f, 0.02f, 0.025f, 0.0f);  // alpha 0: background, for the metrics
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  if (viewIsDepthMap(params.view) && !gbuffer) {
    drawDepthView(frame, key, fill);
    return;
  }
  {
    auto pass = frame.pass(gbuffer ? "reference g-buffer" : "lighting");
    drawLit(frame, fetch(kLitSlot, litSpec(params, internalView_)), key, params.fillLight && !gbuffer ? &fill : nullptr);
  }
  if (params.showFrustum && !gbuffer) drawFrustum(frame, key);
}

void ShadowsLab::drawDepthView(Frame& frame, const LightFrame& key, const LightFrame& fill) {
  auto pass = frame.pass("depth map view");
  const bool showFill = params.depthLight == 1;
  const ShadowMap& map = showFill ? fillMap_ : keyMap_;
  if (!map) return;  // that light casts no shadow: there is no map to show (warnings() says so)
  Program& prog = fetch(kDepthViewSlot, depthViewSpec(params));
  prog.use();
  setLight(prog, "u_key", showFill ? fill : key, params.mapSize());
  prog.set("u_keyMap", int(kKeyMap));
  prog.set("u_keyCube", int(kKeyCube));
  dummies_.bind2D(kKeyMap);
  dummies_.bindCube(kKeyCube);
  if (map.cube()) map.bind(kKeyCube, kKeyCmpCube, true);
  else map.bind(kKeyMap, kKeyCmp, true);
  const float aspect = frame.aspect(), cells = map.cube() ? 4.0f / 3.0f : 1.0f;
  prog.set("u_aspect", aspect > cells ? glm::vec2(aspect / cells, 1.0f) : glm::vec2(1.0f, cells / aspect));
  prog.set("u_zoom", params.depthZoom);
  prog.set("u_centre", glm::vec2(params.depthCentreU, params.depthCentreV));
  glDisable(GL_DEPTH_TEST);
  glBindVertexArray(emptyVao_.get());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  for (int unit = 0; unit <= kKeyCmpCube; ++unit) glBindSampler(unit, 0);
}

std::vector<std::string> ShadowsLab::warnings() const {
  std::vector<std::string> w = lightWarnings_;
  const auto& p = params;
  if (p.keyType != LightType::Point && p.elevationDeg < 10.0f)
    w.push_back("grazing light (" + formatNumber(p.elevationDeg) + " deg above the horizon): texels stretch along the "
                "ground; expect acne unless the slope bias grows");
  if (p.keyCasts && p.bias == 0 && p.slopeBias == 0 && p.normalOffset == 0 && p.offsetFactor == 0 && p.offsetUnits == 0)
    w.push_back("no bias at all: lit surfaces shadow themselves (acne)");
  if (p.bias + p.slopeBias > 12.0f || p.normalOffset > 6.0f)
    w.push_back("large bias: shadows detach from their casters (peter-panning)");
  if (!p.borderClamp) w.push_back("border clamp off: outside the map the edge texels repeat and stretch shadows");
  if (!p.farFix) w.push_back("far-plane fix off: receivers beyond the light's far plane come out shadowed");
  if (p.filter == ShadowFilter::Pcss && p.lightRadius == 0.0f)
    w.push_back("light radius 0: PCSS reduces to a hard shadow");
  if (p.filter == ShadowFilter::Pcss && p.lightRadius > 1.0f)
    w.push_back("light radius " + formatNumber(p.lightRadius) + " scene radii: larger than the scene, penumbrae wash out");
  if (p.keyType == LightType::Point && p.lightDistance < 0.5f)
    w.push_back("point light near the scene centre: it may sit inside geometry, which then hides everything");
  if (!p.keyCasts && !(p.fillLight && p.fillCasts)) w.push_back("no light casts shadows: no depth pass runs");
  if (viewIsDepthMap(p.view) && p.depthLight == 1 && !(p.fillLight && p.fillCasts))
    w.push_back("the depth view shows the fill light's map: turn on fill_light and fill_casts");
  if (viewIsDepthMap(p.view) && p.depthLight == 0 && !p.keyCasts)
    w.push_back("the depth view shows the key light's map, but the key light casts no shadow");
  if ((p.view == ShadowView::PcssBlocker || p.view == ShadowView::PcssPenumbra) && p.filter != ShadowFilter::Pcss)
    w.push_back("the PCSS views show data only with filter = pcss");
  return w;
}

}  // namespace shadelab

#include "labs/shadows/shadows_lab.h"

#include <cstdio>

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_inverse.hpp>

#include "labs/shadows/ray_visibility.h"
#include "labs/shadows/shadow_options.h"

namespace shadelab {
namespace {

// Texture units of lit.frag's samplers, fixed so no two sampler types ever share a unit.
enum Unit {
  kKeyMap = 0,
  kKeyCube,
  kKeyCmp,
  kKeyCmpCube,
  kFillMap,
  kFillCmp,
  kNoCube,
  kNoCmpCube,
  kKeyMoments,
  kFillMoments
};
enum Slot {
  kLitSlot = 0,
  kKeyDepthSlot,
  kFillDepthSlot,
  kDepthViewSlot,
  kLinesSlot,
  kBlurSlot,
  kRangeFirstSlot,
  kRangeSlot,
  kSlotCount
};

// The moments a filtered map holds where nothing was drawn (depth t = 1): warpDepth(1) in
// shadow_filters.glsl.
glm::vec4 farMoments(const ShadowsParams& p, ShadowFilter f) {
  if (f == ShadowFilter::Esm) return glm::vec4(std::exp(p.filter.esmExponent), 0, 0, 0);
  if (f == ShadowFilter::Evsm) {
    const float pos = std::exp(p.filter.evsmPositive), neg = -std::exp(-p.filter.evsmNegative);
    return {pos, pos * pos, neg, neg * neg};
  }
  return glm::vec4(1.0f, 1.0f, 0.0f, 0.0f);
}

}  // namespace

ShadowsLab::ShadowsLab() = default;
ShadowsLab::~ShadowsLab() = default;

std::string_view ShadowsLab::summary() const {
  return "A shadow map stores, per texel, the depth of the nearest surface seen from the light; a pixel is in "
         "shadow when it lies farther than that. Walk the path: set bias to 0 (acne), raise it (peter-panning), "
         "turn off border clamp and the far fix (the artifacts they remove), then PCF, Poisson and PCSS, and the "
         "filtered maps (VSM, ESM, EVSM). On the learnopengl scene, fit the map to the view or split it into "
         "cascades. Every step is measured against ray-traced visibility of a point and of an area light.";
}

SceneNeeds ShadowsLab::needs() const {
  SceneNeeds n;
  n.tessellation = params.scene.tessellation;
  n.scale = params.scene.scale;
  n.groundUnderFiles = params.scene.floorUnderFiles;
  return n;
}

LightSetup ShadowsLab::keySetup() const {
  // The key light's section is its placement and the map's section its frustum: nothing to copy.
  return {params.key, params.map, params.key.sceneLight ? sceneLight_ : glm::vec3(0.0f)};
}

LightSetup ShadowsLab::fillSetup() const {
  LightSetup s;
  s.type = LightType::Spot;
  s.azimuthDeg = params.key.azimuthDeg + 150.0f;
  s.elevationDeg = 35.0f;
  s.distance = 3.0f;
  s.spotAngleDeg = 60.0f;
  return s;
}

std::string ShadowsLab::setup(LabContext& ctx) {
  shaders_ = &ctx.shaders;
  softwareRenderer_ = gl::softwareRenderer();
  geometryShaders_ = gl::hasGeometryShaders();
  programs_.assign(kSlotCount, ProgramSlot{});
  dummies_.create();
  emptyVao_ = gl::VertexArray::make();
  // The 12 edges of the NDC cube, drawn through the light's inverse view-projection.
  const glm::vec3 c[8] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                          {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
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
  // Cube-map lookups near a face's edge filter across into the next face (core since 3.2).
  if (geometryShaders_) glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);  // desktop GL; always on in ES 3.0
  return {};
}

std::vector<ProgramRef> ShadowsLab::activePrograms() const { return heldPrograms(programs_); }

const std::vector<glm::vec2>& ShadowsLab::disk(int count) {
  // Each set is made the first time a filter asks for it (dart throwing takes tens of ms for 64).
  switch (std::clamp(count, 8, 64)) {
    case 8: {
      static const std::vector<glm::vec2> d = poissonDisk(8);
      return d;
    }
    case 16: {
      static const std::vector<glm::vec2> d = poissonDisk(16);
      return d;
    }
    case 32: {
      static const std::vector<glm::vec2> d = poissonDisk(32);
      return d;
    }
    default: {
      static const std::vector<glm::vec2> d = poissonDisk(64);
      return d;
    }
  }
}

ShadowFilter ShadowsLab::effectiveFilter() const { return effectiveFilterOf(params); }

static void setLight(Program& prog, const std::string& n, const LightFrame& L, int mapSize, int layer = 0) {
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
  prog.set((n + ".layer").c_str(), float(layer));
}

void ShadowsLab::setFilterUniforms(Program& prog) const {
  const ShadowFilter filter = effectiveFilterOf(params);
  prog.set("u_bias", params.bias.constant);
  prog.set("u_slopeBias", params.bias.slope);
  prog.set("u_normalOffset", params.bias.normalOffset);
  prog.set("u_filterRadius", params.filter.poissonRadius);
  // The disks only where the variant samples them (Poisson, PCSS): made on first use, not for PCF.
  if (prog.uses("u_filterDisk")) {
    const auto& taps =
        disk(filter == ShadowFilter::Pcss ? 8 << params.filter.pcssIndex : 8 << params.filter.poissonIndex);
    prog.setArray("u_filterDisk", taps.data(), int(taps.size()));
  }
  if (prog.uses("u_blockerDisk")) {
    const auto& taps = disk(8 << params.filter.blockerIndex);
    prog.setArray("u_blockerDisk", taps.data(), int(taps.size()));
  }
  prog.set("u_minVariance", params.filter.minVariance);
  prog.set("u_bleed", params.filter.bleedReduction);
  prog.set("u_esmExponent", params.filter.esmExponent);
  prog.set("u_evsmExponents", glm::vec2(params.filter.evsmPositive, params.filter.evsmNegative));
}

void ShadowsLab::drawLit(Frame& frame, Program& prog, const LightFrame& key, const LightFrame* fill) {
  const Bounds b = frame.scene.bounds;
  prog.use();
  prog.set("u_viewProj", frame.viewProj());
  prog.set("u_eye", frame.camera.eye());
  prog.set("u_ambient", 0.12f);
  setLight(prog, "u_key", cascades_.empty() ? key : cascades_[0].light, sizeOf(keyMap_));
  if (cascades_.size() >= 2) {
    for (size_t i = 0; i < cascades_.size(); ++i) {
      prog.set(("u_cascadeBox[" + std::to_string(i) + "]").c_str(), cascadeBox(cascades_[0].light, cascades_[i].light));
      prog.set(("u_cascadeFar[" + std::to_string(i) + "]").c_str(), cascades_[i].splitFar);
      prog.set(("u_blendFrom[" + std::to_string(i) + "]").c_str(), cascades_[i].blendFrom);
    }
    prog.set("u_viewForward", glm::normalize(frame.camera.target - frame.camera.eye()));
  }
  // Irradiance 1 at the scene centre whatever the light type and scale.
  const float keyR2 =
      key.type == LightType::Directional ? 1.0f : glm::dot(key.position - b.center(), key.position - b.center());
  prog.set("u_keyPower", glm::vec3(1.0f, 0.97f, 0.92f) * keyR2);
  setFilterUniforms(prog);
  const struct {
    const char* name;
    int unit;
  } units[] = {{"u_keyMap", kKeyMap},          {"u_keyCube", kKeyCube},     {"u_keyCmp", kKeyCmp},
               {"u_keyCmpCube", kKeyCmpCube},  {"u_fillMap", kFillMap},     {"u_fillCmp", kFillCmp},
               {"u_noCube", kNoCube},          {"u_noCmpCube", kNoCmpCube}, {"u_keyMoments", kKeyMoments},
               {"u_fillMoments", kFillMoments}};
  for (auto& u : units) prog.set(u.name, u.unit);
  // Each sampler the variant really samples gets a texture of its type on its own unit: the real
  // map, or a 1x1 dummy. Units the variant does not read are left alone (every binding is state
  // the driver checks at the next draw).
  const bool keyReal = keyMap_ && params.key.casts, fillReal = fill && fillMap_ && params.fill.casts;
  boundSamplers_.clear();
  auto bindMap = [&](ShadowMap& map, bool real, bool cube, const char* raw, const char* cmp, int rawUnit, int cmpUnit) {
    if (!prog.uses(raw) && !prog.uses(cmp)) return;
    if (real && map.cube() == cube) {
      map.bind(rawUnit, cmpUnit, params.map.borderClamp);
      boundSamplers_.insert(boundSamplers_.end(), {rawUnit, cmpUnit});
    } else {
      for (int unit : {rawUnit, cmpUnit}) {
        cube ? dummies_.bindCube(unit, unit == cmpUnit) : dummies_.bindArray(unit, unit == cmpUnit);
        boundSamplers_.push_back(unit);
      }
    }
  };
  auto bindMoments = [&](ShadowMap& map, bool real, const char* name, int unit) {
    if (!prog.uses(name)) return;
    if (real && map.hasMoments()) {
      map.bindMoments(unit);
      boundSamplers_.push_back(unit);
    } else {
      dummies_.bindMoments(unit);
    }
  };
  bindMap(keyMap_, keyReal, false, "u_keyMap", "u_keyCmp", kKeyMap, kKeyCmp);
  bindMap(keyMap_, keyReal, true, "u_keyCube", "u_keyCmpCube", kKeyCube, kKeyCmpCube);
  bindMoments(keyMap_, keyReal, "u_keyMoments", kKeyMoments);
  bindMap(fillMap_, fillReal, false, "u_fillMap", "u_fillCmp", kFillMap, kFillCmp);
  bindMoments(fillMap_, fillReal, "u_fillMoments", kFillMoments);
  if (prog.uses("u_noCube") || prog.uses("u_noCmpCube"))
    for (int unit : {kNoCube, kNoCmpCube}) {
      dummies_.bindCube(unit, unit == kNoCmpCube);
      boundSamplers_.push_back(unit);
    }
  if (fill) {
    setLight(prog, "u_fill", *fill, sizeOf(fillMap_));
    const float r2 = glm::dot(fill->position - b.center(), fill->position - b.center());
    prog.set("u_fillPower", glm::vec3(0.35f, 0.45f, 0.6f) * r2);
  }
  for (size_t i : frame.scene.nearestFirst(frame.camera.eye())) {
    const Instance& inst = frame.scene.instances[i];
    const Material& mat = frame.scene.materials[size_t(frame.scene.meshes[size_t(inst.mesh)].material)];
    prog.set("u_model", inst.model);
    prog.set("u_normalMatrix", glm::mat3(glm::inverseTranspose(inst.model)));
    prog.set("u_baseColor", mat.baseColor);
    frame.gpu.draw(inst);
  }
  // Sampler objects override texture state: leave none bound for whoever draws next.
  for (int unit : boundSamplers_) glBindSampler(GLuint(unit), 0);
}

void ShadowsLab::drawFrustum(Frame& frame, const LightFrame& key) {
  if (key.type == LightType::Point) return;
  auto pass = frame.pass("light frustum");
  Program& prog = fetch(kLinesSlot, linesSpec());
  prog.use();
  prog.set("u_viewProj", frame.viewProj());
  prog.set("u_color", glm::vec3(1.0f, 0.85f, 0.2f));
  glBindVertexArray(frustumVao_.get());
  if (cascades_.empty()) {
    prog.set("u_lightInverse", glm::inverse(key.viewProj));
    glDrawArrays(GL_LINES, 0, 24);
  }
  for (const Cascade& c : cascades_) {  // every cascade's box
    prog.set("u_lightInverse", glm::inverse(c.light.viewProj));
    glDrawArrays(GL_LINES, 0, 24);
  }
}

static ViewVolume viewVolume(const Frame& frame) {
  ViewVolume v;
  v.inverseViewProj = glm::inverse(frame.viewProj());
  v.eye = frame.camera.eye();
  v.forward = glm::normalize(frame.camera.target - v.eye);
  v.nearPlane = frame.camera.nearPlane;
  v.farPlane = frame.camera.farPlane;
  return v;
}

bool ShadowsLab::ensureMap(ShadowMap& map, const MapShape& shape, const char* which, double budgetBytes) {
  const int got = map.ensure(shape, budgetBytes);
  if (got == shape.size) return true;
  auto bytes = [](double b) {
    const double mib = b / double(1 << 20);
    char text[32];
    std::snprintf(text, sizeof text, mib >= 1024.0 ? "%.1f GiB" : "%.0f MiB", mib >= 1024.0 ? mib / 1024.0 : mib);
    return std::string(text);
  };
  const std::string asked =
      std::to_string(shape.size) + "^2 " + which + " shadow map (" + bytes(ShadowMap::bytesOf(shape)) + ")";
  MapShape drawn = shape;
  drawn.size = got;
  const std::string instead = "; drawing at " + std::to_string(got) + "^2 (" + bytes(ShadowMap::bytesOf(drawn)) +
                              ") instead: pick a smaller map size, fewer cascades or a depth-only filter";
  static_assert(ShadowMap::kBudgetBytes == 2.0 * 1024 * 1024 * 1024, "the message below names the budget");
  const double othersTake = ShadowMap::kBudgetBytes - budgetBytes;
  if (got && ShadowMap::bytesOf(shape) > budgetBytes)
    mapWarnings_.push_back("a " + asked + " is over the lab's 2 GiB budget for shadow maps" +
                           (othersTake > 0.0 ? " (the key light's maps take " + bytes(othersTake) + " of it)" : "") +
                           instead);
  else
    mapWarnings_.push_back(got ? "the driver could not allocate a " + asked + instead
                               : "the driver could not allocate even a 256^2 " + std::string(which) +
                                     " shadow map: no shadow from that light");
  return got > 0;
}

void ShadowsLab::renderKeyMaps(Frame& frame, const LightFrame& key, const DepthPassState& state, GLenum format) {
  const bool cube = params.key.type == LightType::Point;
  const ShadowFilter filter = effectiveFilterOf(params);
  const int layers = std::max<int>(int(cascades_.size()), 1);
  if (!ensureMap(keyMap_,
                 {cube, params.map.size(), layers, format, cube ? 0u : momentFormat(filter), params.filter.momentMips},
                 "key", ShadowMap::kBudgetBytes))
    return;
  const std::string size =
      std::to_string(keyMap_.size()) + "^2 D" + std::string(rowOf(kDepthFormats, params.map.format).name);
  // The first cascade says which view depths the set was split over, and for the depth-range fit
  // whether they are the depths drawn last frame or (none from this camera yet) the frustum's.
  const bool depthRangeFit = cascades_.size() >= 2 && params.map.fit == MapFit::DepthRange;
  char split[96] = "";
  if (cascades_.size() >= 2)
    std::snprintf(split, sizeof split, " (split over %.3g to %.3g%s)", cascades_[0].splitRange.x,
                  cascades_[0].splitRange.y,
                  !depthRangeFit ? ""
                  : drawnRange_  ? " drawn last frame"
                                 : ": the frustum's, no depth drawn yet");
  const std::string kind = std::string(rowOf(kLightTypes, params.key.type).name) +
                           (depthRangeFit                                          ? " depth-range cascade "
                            : cascades_.size() >= 2                                ? " cascade "
                            : params.map.fit == MapFit::View && !cascades_.empty() ? " view-fitted"
                                                                                   : "");
  Program& depth = fetch(kKeyDepthSlot, depthSpec(cube, sixCubePasses(), filter));
  if (isMomentFilter(filter)) {
    depth.use();
    setFilterUniforms(depth);  // the moment pass warps depth with the same exponents the lookups use
  }
  for (int layer = 0; layer < layers; ++layer) {
    auto pass =
        frame.pass("shadow map: key " + kind + (cascades_.size() >= 2 ? std::to_string(layer + 1) : "") + " " + size +
                   (cube ? (sixCubePasses() ? " x6 (6 passes)" : " x6 (1 pass)") : "") +
                   (keyMap_.hasMoments() ? " + " + filterName(filter) + " moments" : "") + (layer == 0 ? split : ""));
    keyMap_.render(frame.scene, frame.gpu, depth, cascades_.empty() ? key : cascades_[size_t(layer)].light, layer,
                   state);
  }
  if (keyMap_.hasMoments() && (params.filter.blurRadius > 0 || params.filter.momentMips)) {
    auto pass = frame.pass("moment blur " + std::to_string(params.filter.blurRadius) + " texels" +
                           (params.filter.momentMips ? " + mips" : ""));
    keyMap_.filterMoments(fetch(kBlurSlot, blurSpec()), params.filter.blurRadius, emptyVao_.get());
  }
}

void ShadowsLab::render(Frame& frame) {
  const Bounds bounds = frame.scene.bounds;
  sceneLight_ = frame.scene.suggestedLight;
  lightWarnings_.clear();
  mapWarnings_.clear();
  const LightFrame key = buildLight(keySetup(), bounds, lightWarnings_);
  std::vector<std::string> ignored;
  const LightFrame fill = buildLight(fillSetup(), bounds, ignored);
  const GLenum format = rowOf(kDepthFormats, params.map.format).internalFormat;
  const ShadowFilter filter = effectiveFilterOf(params);
  DepthPassState depthState{params.map.cullFront, params.bias.offsetFactor, params.bias.offsetUnits, sixCubePasses()};
  depthState.momentClear = farMoments(params, filter);
  const bool gbuffer = internalView_ != InternalView::None;

  // The key light's maps: the scene-fitted one, or fitted to the view, or one per cascade.
  cascades_.clear();
  const bool fitToDepth = params.map.fit == MapFit::DepthRange && cascadeCountOf(params) > 0;
  drawnRange_ = fitToDepth ? depthRange_.rangeFor(frame.viewProj()) : std::nullopt;
  if (!fitToDepth) depthRange_.release();
  if (const int count = cascadeCountOf(params); count > 0)
    cascades_ = buildCascades(
        key, {count, params.map.splitLambda, params.map.cascadeBlend, params.map.snapTexels, params.map.size()},
        viewVolume(frame), bounds, frame.scene.instanceBounds, drawnRange_);

  // 1. Depth passes, only for lights that cast and only when the view reads their maps.
  if (params.key.casts && !gbuffer) {
    renderKeyMaps(frame, key, depthState, format);
  } else if (!params.key.casts) {
    keyMap_.release();  // (a g-buffer render keeps it: the next frame needs it again)
  }
  const bool fillMapNeeded = params.fill.on && params.fill.casts && !gbuffer &&
                             (!viewIsDepthMap(params.view.mode) || params.view.depthLight == 1);
  // The fill light's map gets what the key light's leave of the lab's budget.
  const double fillBudget = ShadowMap::kBudgetBytes - (params.key.casts ? keyMap_.bytes() : 0.0);
  if (fillMapNeeded &&
      ensureMap(fillMap_, {false, params.map.size(), 1, format, momentFormat(filter), params.filter.momentMips}, "fill",
                fillBudget)) {
    const std::string size =
        std::to_string(fillMap_.size()) + "^2 D" + std::string(rowOf(kDepthFormats, params.map.format).name);
    {
      auto pass = frame.pass("shadow map: fill spot " + size +
                             (isMomentFilter(filter) ? " + " + filterName(filter) + " moments" : ""));
      Program& depth = fetch(kFillDepthSlot, depthSpec(false, false, filter));
      if (isMomentFilter(filter)) {
        depth.use();
        setFilterUniforms(depth);
      }
      fillMap_.render(frame.scene, frame.gpu, depth, fill, 0, depthState);
    }
    if (fillMap_.hasMoments() && (params.filter.blurRadius > 0 || params.filter.momentMips)) {
      auto pass = frame.pass("moment blur (fill)");
      fillMap_.filterMoments(fetch(kBlurSlot, blurSpec()), params.filter.blurRadius, emptyVao_.get());
    }
  } else if (!(params.fill.on && params.fill.casts)) {
    fillMap_.release();
  }

  // 2. The camera pass: the lit scene (or a diagnostic view of it), or a map itself.
  frame.target.bind();
  glDisable(GL_CULL_FACE);
  glEnable(GL_DEPTH_TEST);
  glClearColor(0.02f, 0.02f, 0.025f, 0.0f);  // alpha 0: background, for the metrics
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  if (viewIsDepthMap(params.view.mode) && !gbuffer) {
    drawDepthView(frame, key, fill);
    return;
  }
  {
    auto pass = frame.pass(gbuffer ? "reference g-buffer" : "lighting");
    drawLit(frame, fetch(kLitSlot, litSpec(params, internalView_)), key, params.fill.on && !gbuffer ? &fill : nullptr);
  }
  if (fitToDepth && params.key.casts && !gbuffer) {
    auto pass = frame.pass("depth range: nearest and farthest depth drawn (for the next frame's cascades)");
    depthRange_.reduce(frame.target, frame.viewProj(), {frame.camera.nearPlane, frame.camera.farPlane},
                       fetch(kRangeFirstSlot, DepthRange::programSpec(true)),
                       fetch(kRangeSlot, DepthRange::programSpec(false)), emptyVao_.get());
  }
  if (params.view.showFrustum && !gbuffer) drawFrustum(frame, key);
}

// The square of each cube face (in its [-1, 1]^2 coordinates: centre, half size) that holds what the
// scene's boxes project to, a little padded, and {0, 0, 0} where the face sees no box at all. The
// faces follow depth_view.frag's cross: direction = axis + x U + y V.
std::array<glm::vec3, 6> cubeFaceWindows(std::span<const Bounds> boxes, glm::vec3 light, bool frame) {
  struct Face {
    glm::vec3 axis, u, v;
  };
  static constexpr Face kFaces[6] = {{{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}}, {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},
                                     {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}}, {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}},
                                     {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}}, {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}}};
  std::array<glm::vec3, 6> out;
  for (int i = 0; i < 6; ++i) {
    const Face& f = kFaces[i];
    glm::vec2 lo(INFINITY), hi(-INFINITY);
    for (const Bounds& box : boxes) {
      if (box.empty() || !frame) continue;
      // The box's part in front of the face's plane projects inside the hull of its front corners
      // and of the points where its edges cross the plane (taken a hair in front: far out, then
      // clamped to the face).
      const auto depthOf = [&](int c) { return glm::dot(box.corner(c) - light, f.axis); };
      const auto project = [&](glm::vec3 p) {
        const float depth = glm::dot(p, f.axis);
        const glm::vec2 q(glm::dot(p, f.u) / depth, glm::dot(p, f.v) / depth);
        lo = glm::min(lo, q), hi = glm::max(hi, q);
      };
      const float hair = 1e-5f * glm::length(box.max - box.min) + 1e-12f;
      for (int c = 0; c < 8; ++c) {
        if (depthOf(c) > hair) project(box.corner(c) - light);
        for (int bit : {1, 2, 4}) {
          if (c & bit) continue;
          const float da = depthOf(c), db = depthOf(c | bit);
          if ((da > hair) == (db > hair)) continue;
          const float t = (hair - da) / (db - da);
          project(glm::mix(box.corner(c), box.corner(c | bit), t) - light);
        }
      }
    }
    lo = glm::max(lo, glm::vec2(-1.0f)), hi = glm::min(hi, glm::vec2(1.0f));
    if (!frame)
      out[size_t(i)] = {0.0f, 0.0f, 1.0f};
    else if (!(hi.x > lo.x && hi.y > lo.y))
      out[size_t(i)] = glm::vec3(0.0f);  // sees nothing
    else {
      const float half = std::min(0.5f * std::max(hi.x - lo.x, hi.y - lo.y) * 1.08f, 1.0f);
      const glm::vec2 centre = glm::clamp(0.5f * (lo + hi), glm::vec2(half - 1.0f), glm::vec2(1.0f - half));
      out[size_t(i)] = {centre, half};
    }
  }
  return out;
}

void ShadowsLab::drawDepthView(Frame& frame, const LightFrame& key, const LightFrame& fill) {
  auto pass = frame.pass("depth map view");
  const bool showFill = params.view.depthLight == 1;
  ShadowMap& map = showFill ? fillMap_ : keyMap_;
  if (!map) return;  // that light casts no shadow: there is no map to show (warnings() says so)
  const int layer = showFill ? 0 : std::min(params.view.depthCascade, map.layers() - 1);
  const LightFrame& shown = showFill ? fill : cascades_.empty() ? key : cascades_[size_t(layer)].light;
  Program& prog = fetch(kDepthViewSlot, depthViewSpec(params));
  prog.use();
  setLight(prog, "u_key", shown, sizeOf(map), layer);
  prog.set("u_keyMap", int(kKeyMap));
  prog.set("u_keyCube", int(kKeyCube));
  dummies_.bindArray(kKeyMap, false);
  dummies_.bindCube(kKeyCube, false);
  if (map.cube())
    map.bind(kKeyCube, kKeyCmpCube, true);
  else
    map.bind(kKeyMap, kKeyCmp, true);
  // The distances the map's content occupies from this light: what the linear view stretches to
  // white (a cascade holds a thin slice of the scene; the whole scene's range would show it grey).
  const Bounds& b = frame.scene.bounds;
  glm::vec2 range;
  if (shown.type == LightType::Point) {
    // A cube sees all around: from the nearest point of any instance's box to its farthest corner
    // (the scene's bounding sphere, seen from a light beside it, spans several times that).
    range = glm::vec2(INFINITY, 0.0f);
    for (const Bounds& box : frame.scene.instanceBounds) {
      if (box.empty()) continue;
      range.x = std::min(range.x, glm::length(glm::clamp(shown.position, box.min, box.max) - shown.position));
      for (int c = 0; c < 8; ++c) range.y = std::max(range.y, glm::length(box.corner(c) - shown.position));
    }
    if (!(range.y > range.x)) range = glm::vec2(0.0f, glm::length(b.center() - shown.position) + b.radius());
    range.x = std::max(range.x, shown.nearPlane);
  } else {
    const float centre = glm::dot(b.center() - shown.position, shown.direction);
    range = glm::vec2(std::max(centre - b.radius(), shown.nearPlane), centre + b.radius());
  }
  if (!showFill && !cascades_.empty()) range = cascades_[size_t(layer)].contentDepth;
  prog.set("u_range", range);
  glm::vec2 grid(1.0f);  // the view's cells across and down: one map, the cube's cross, or its framed faces
  if (map.cube()) {
    const auto windows = cubeFaceWindows(frame.scene.instanceBounds, shown.position, params.view.frameFaces);
    prog.setArray("u_faceWindow", windows.data(), int(windows.size()));
    int faces = 0;
    for (int face = 0; face < 6; ++face)
      if (params.view.frameFaces && windows[size_t(face)].z > 0.0f)
        prog.set(("u_faces[" + std::to_string(faces++) + "]").c_str(), face);
    prog.set("u_faceCount", faces);
    grid = faces == 0 ? glm::vec2(4.0f, 3.0f) : glm::vec2(std::min(faces, 3), (faces + 2) / 3);
  }
  const float aspect = frame.aspect(), cells = grid.x / grid.y;
  prog.set("u_aspect", aspect > cells ? glm::vec2(aspect / cells, 1.0f) : glm::vec2(1.0f, cells / aspect));
  prog.set("u_zoom", params.view.depthZoom);
  prog.set("u_centre", glm::vec2(params.view.depthCentreU, params.view.depthCentreV));
  glDisable(GL_DEPTH_TEST);
  glBindVertexArray(emptyVao_.get());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  for (int unit = 0; unit <= kKeyCmpCube; ++unit) glBindSampler(unit, 0);
}

}  // namespace shadelab

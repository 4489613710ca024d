// The shadows lab against ground truth: ray-traced visibility of the key light (Embree), the
// error numbers, the standard sweep and the stress cases.
#include <chrono>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "app/scene/procedural.h"

#include "labs/shadows/ray_visibility.h"
#include "labs/shadows/shadow_options.h"
#include "labs/shadows/shadows_lab.h"

namespace shadelab {

ReferenceSpec ShadowsLab::reference() const {
  // The truth depends on the scene, the camera and the light (its position and radius); never on
  // the map, its fit, the bias or the filter. These overrides name the truth's settings, so a
  // sweep traces it once for every filter.
  ReferenceSpec spec;
  spec.kind = TruthKind::Image;
  spec.traced = true;
  spec.displayEncoded = false;  // visibility, not colour
  spec.overrides = edits<ShadowsLab>(params, [](ShadowsParams& p) {
    p.filter.type = ShadowFilter::Hard;
    p.filter.pcfSize = 3;
    p.map.sizeIndex = ShadowsParams::Map::sizeIndexOf(2048);
    p.map.format = DepthFormat::D24;
    p.map.fit = MapFit::Scene;
    p.map.cullFront = false;
    p.map.borderClamp = p.map.farFix = true;
    p.bias = {};  // the default bias, all of it
    p.view.mode = ShadowView::Visibility;
    p.view.showFrustum = false;
    p.fill.on = false;
  });
  spec.tracedOnGl = tracesOnGpu();
  spec.truth = spec.tracedOnGl ? "ray-traced on the GPU" : "ray-traced by Embree";
  // The GPU trace runs in bands of about 25 ms between frames and a newer one supersedes it, so
  // Auto can follow the sliders (on a GPU the 64 samples land within a few frames).
  spec.cheap = spec.tracedOnGl;
  spec.description =
      std::string(spec.tracedOnGl ? "GPU ray-traced (a BVH in a fragment shader)" : "Embree ray-traced") +
      " visibility of the key light on the same triangles and camera, two truths in "
      "one image: the point light (one ray per pixel; visibility_rmse_hard, misclassified_pct, acne_pct, "
      "leak_pct) and the area light of light_radius (8x8 stratified rays over its disk; "
      "visibility_rmse_area)";
  return spec;
}

TraceWork ShadowsLab::traceReference(Frame& frame) {
  if (!rayScene_ || rayRevision_ != frame.scene.revision) {
    rayScene_ = std::make_shared<const RayScene>(frame.scene);
    rayRevision_ = frame.scene.revision;
  }
  sceneLight_ = frame.scene.suggestedLight;
  // Positions and normals of exactly the pixels the rasteriser draws, in full float precision.
  const gl::RenderTarget gbuffer = gl::RenderTarget::create(frame.size(), GL_RGBA32F);
  Frame g{gbuffer, frame.scene, frame.gpu, frame.camera, frame.timer, frame.time};
  internalView_ = InternalView::Position;
  render(g);
  ImageF positions{gbuffer.size(), gbuffer.readRgba()};
  internalView_ = InternalView::Normal;
  render(g);
  ImageF normals{gbuffer.size(), gbuffer.readRgba()};
  internalView_ = InternalView::None;
  glBindFramebuffer(GL_FRAMEBUFFER, 0);

  const Bounds bounds = frame.scene.bounds;
  std::vector<std::string> ignored;
  const LightFrame key = buildLight(keySetup(), bounds, ignored);
  const float epsilon = 2e-4f * bounds.radius();  // lifts ray origins off the surface they start on
  // The rays are the slow part (seconds for an area light): a job, which owns all it reads.
  return [scene = rayScene_, key, positions = std::move(positions), normals = std::move(normals),
          epsilon](JobContext& job) { return rayTracedVisibility(*scene, key, positions, normals, 8, epsilon, &job); };
}

void ShadowsLab::setTracerShape(GpuShadowTracer::Shape shape) {
  tracerShape_ = shape;
  tracer_.reset();  // the next truth starts a tracer of this shape (its BVH is built anew)
}

GlTraceStep ShadowsLab::traceReferenceOnGl(Frame& frame) {
  if (!tracer_) tracer_ = std::make_unique<GpuShadowTracer>(tracerShape_);
  tracer_->prepare(frame.scene);
  sceneLight_ = frame.scene.suggestedLight;
  // The g-buffer as the Embree truth reads it, kept on the GPU for the tracer's passes.
  for (auto [target, view] : {std::pair{&tracer_->positions(frame.size()), InternalView::Position},
                              std::pair{&tracer_->normals(frame.size()), InternalView::Normal}}) {
    Frame g{*target, frame.scene, frame.gpu, frame.camera, frame.timer, frame.time};
    internalView_ = view;
    render(g);
  }
  internalView_ = InternalView::None;
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  const Bounds bounds = frame.scene.bounds;
  std::vector<std::string> ignored;
  const LightFrame key = buildLight(keySetup(), bounds, ignored);
  tracer_->begin(key, 8, 2e-4f * bounds.radius());
  standardError_ = 0.0;
  errorAt_ = 0;
  GpuShadowTracer* tracer = tracer_.get();
  auto lastRead = std::chrono::steady_clock::now();
  return [this, tracer, lastRead](JobContext& job) mutable -> std::optional<ImageF> {
    if (tracer_.get() != tracer || !shaders_) return ImageF{};  // the lab was torn down: nothing to trace with
    const bool more = tracer->step(*shaders_, tracePrograms_) && !job.cancelled();
    const int done = tracer->samplesDone();
    std::optional<ImageF> image;
    if (!more) {
      image = tracer->result(*shaders_, tracePrograms_, &standardError_);
    } else if (done >= errorAt_ + 8 && std::chrono::steady_clock::now() - lastRead > std::chrono::milliseconds(250)) {
      // The error bar so far: a read-back of the whole sum, so a few times a second at most (a GPU
      // finishes the 64 passes before the first is due).
      tracer->result(*shaders_, tracePrograms_, &standardError_);
      lastRead = std::chrono::steady_clock::now();
      errorAt_ = done;
    }
    job.progress(float(done) / float(tracer->samplesWanted()),
                 "GPU trace " + std::to_string(done) + "/" + std::to_string(tracer->samplesWanted()) +
                     (errorAt_ > 0 || !more ? ", mean std. error " + formatFixed(standardError_, 4) : ""));
    return image;
  };
}

Metrics ShadowsLab::metrics(const ImageF& image, const ImageF& reference) const {
  if (image.size != reference.size)
    return {{"misclassified_pct", 100}, {"visibility_rmse_hard", 1}, {"visibility_rmse_area", 1},
            {"acne_pct", 100},          {"leak_pct", 100},           {"valid_pct", 0}};
  double valid = 0, wrong = 0, hardSq = 0, areaSq = 0, lit = 0, acne = 0, shadowed = 0, leak = 0;
  const size_t pixels = size_t(image.size.x) * image.size.y;
  for (size_t i = 0; i < pixels; ++i) {
    // Only surfaces that face the key light (and lie in a spot's cone) have a shadow question.
    if (image.rgba[i * 4 + 3] < 0.5f || reference.rgba[i * 4 + 3] < 0.5f) continue;
    const double v = image.rgba[i * 4], hard = reference.rgba[i * 4], area = reference.rgba[i * 4 + 1];
    valid += 1;
    wrong += (v >= 0.5) != (hard >= 0.5);
    hardSq += (v - hard) * (v - hard);
    areaSq += (v - area) * (v - area);
    if (hard >= 0.99) {  // truly lit: shadowed by the map there is acne (or a blur spilling over)
      lit += 1;
      acne += v < 0.5;
    }
    if (hard <= 0.01) {  // truly shadowed: lit by the map there is a leak (peter-panning)
      shadowed += 1;
      leak += v >= 0.5;
    }
  }
  const double n = std::max(valid, 1.0);
  return {{"misclassified_pct", 100.0 * wrong / n},
          {"visibility_rmse_hard", std::sqrt(hardSq / n)},
          {"visibility_rmse_area", std::sqrt(areaSq / n)},
          {"acne_pct", lit > 0 ? 100.0 * acne / lit : 0.0},
          {"leak_pct", shadowed > 0 ? 100.0 * leak / shadowed : 0.0},
          {"valid_pct", 100.0 * valid / double(pixels)}};
}

Settings ShadowsLab::metricNotes() const {
  return {{"misclassified_pct",
           "pixels whose lit/shadowed verdict (visibility >= 0.5) differs from the point-light "
           "truth's, in % of the pixels that face the key light"},
          {"visibility_rmse_hard", "RMS of (visibility - point-light truth) over the pixels that face the key light"},
          {"visibility_rmse_area", "RMS of (visibility - area-light truth, light_radius) over the same pixels"},
          {"acne_pct",
           "pixels shadowed by the map (< 0.5) where the point-light truth is fully lit, in % of the "
           "fully lit pixels"},
          {"leak_pct",
           "pixels lit by the map (>= 0.5) where the point-light truth is fully shadowed, in % of the "
           "fully shadowed pixels"},
          {"valid_pct", "pixels that face the key light, in % of the image"}};
}

std::vector<SweepAxis> ShadowsLab::standardSweep() const {
  SweepAxis filters{"filter", {}};
  for (const ShadowFilterRow& row : kShadowFilters) {
    if (row.sweep[0].empty()) filters.values.emplace_back(row.name);
    for (std::string_view value : row.sweep)
      if (!value.empty()) filters.values.emplace_back(value);
  }
  return {filters,
          {"map_size", {"512", "1024", "2048", "4096"}},
          {"bias", {"0:slope_bias=0", "2.5:slope_bias=4"}}};  // no bias at all, and the default
}

std::vector<StressCase> ShadowsLab::stressCases() const {
  const auto edit = [](auto change) { return fromDefaults<ShadowsLab>(change); };
  return {
      {"grazing-85", edit([](ShadowsParams& p) { p.key.elevationDeg = 5.0f; }), "", "", "grazing light"},
      {"grazing-89.9", edit([](ShadowsParams& p) { p.key.elevationDeg = 0.1f; }), "", "", "grazing light"},
      {"grazing-89.9-pcss",
       edit([](ShadowsParams& p) { p.key.elevationDeg = 0.1f, p.filter.type = ShadowFilter::Pcss; }), "", "",
       "grazing light"},
      {"point-light-inside-sphere",
       edit([](ShadowsParams& p) { p.key.type = LightType::Point, p.key.distance = 0.0f; }), "sphere", "",
       "inside geometry"},
      {"spot-light-inside-scene", edit([](ShadowsParams& p) { p.key.type = LightType::Spot, p.key.distance = 0.3f; }),
       "", "", "inside the scene"},
      // Points beside the spot's eye project towards infinity; the bilinear taps took fract() of it (NaN).
      {"spot-light-at-the-centre-bilinear", edit([](ShadowsParams& p) {
         p.key.type = LightType::Spot, p.key.distance = 0.0f, p.filter.type = ShadowFilter::PcfBilinear;
       }),
       "", "", "inside the scene"},
      {"near-far-ratio-1e4", edit([](ShadowsParams& p) {
         p.key.type = LightType::Spot, p.map.autoFit = false, p.map.nearPlane = 0.001f, p.map.farPlane = 10.0f;
       }),
       "", "", ""},
      {"near-far-ratio-1e6", edit([](ShadowsParams& p) {
         p.key.type = LightType::Spot, p.map.autoFit = false, p.map.nearPlane = 1e-5f, p.map.farPlane = 10.0f;
       }),
       "", "", "far/near ratio"},
      {"point-near-far-ratio-1e6", edit([](ShadowsParams& p) {
         p.key.type = LightType::Point, p.map.autoFit = false, p.map.nearPlane = 1e-5f, p.map.farPlane = 10.0f;
       }),
       "", "", "far/near ratio"},
      {"near-beyond-far",
       edit([](ShadowsParams& p) { p.map.autoFit = false, p.map.nearPlane = 5.0f, p.map.farPlane = 1.0f; }), "", "",
       "near plane is beyond"},
      {"light-radius-0-pcss", edit([](ShadowsParams& p) { p.filter.type = ShadowFilter::Pcss, p.key.radius = 0.0f; }),
       "", "", "radius 0"},
      {"light-radius-huge-pcss",
       edit([](ShadowsParams& p) { p.filter.type = ShadowFilter::Pcss, p.key.radius = 10.0f; }), "", "",
       "larger than the scene"},
      {"ortho-extent-tiny", edit([](ShadowsParams& p) { p.map.autoFit = false, p.map.orthoExtent = 0.001f; }), "", "",
       "outside the map"},
      {"ortho-extent-huge", edit([](ShadowsParams& p) {
         p.map.autoFit = false, p.map.orthoExtent = 1000.0f, p.map.nearPlane = 0.001f, p.map.farPlane = 10000.0f;
       }),
       "", "", ""},
      {"scene-scale-1e-3", edit([](ShadowsParams& p) { p.scene.scale = 0.001f, p.filter.type = ShadowFilter::Pcss; }),
       "", "", ""},
      {"scene-scale-1e4", edit([](ShadowsParams& p) { p.scene.scale = 10000.0f, p.filter.type = ShadowFilter::Pcss; }),
       "", "", ""},
      {"point-scale-1e-3", edit([](ShadowsParams& p) { p.scene.scale = 0.001f, p.key.type = LightType::Point; }), "",
       "", ""},
      {"pcss-blocker-at-receiver",
       edit([](ShadowsParams& p) { p.filter.type = ShadowFilter::Pcss, p.bias.constant = 0.0f, p.bias.slope = 0.0f; }),
       "", "", "no bias"},
      {"point-pcss", edit([](ShadowsParams& p) {
         p.key.type = LightType::Point, p.filter.type = ShadowFilter::Pcss, p.key.radius = 0.3f;
       }),
       "", "", ""},
      {"no-light-casts", edit([](ShadowsParams& p) { p.key.casts = false; }), "", "", "no light casts"},
      {"empty-scene", edit([](ShadowsParams& p) { p.fill.on = true; }), "empty", "", ""},
      {"map-8192-d32f", edit([](ShadowsParams& p) {
         p.map.sizeIndex = ShadowsParams::Map::sizeIndexOf(8192), p.map.format = DepthFormat::D32F,
         p.filter.type = ShadowFilter::Pcf, p.filter.pcfSize = 15;
       }),
       "", "", ""},
      // Filtered maps: moments of depth in 32-bit float must stay finite however stretched the depth range.
      {"vsm-near-far-ratio-1e6", edit([](ShadowsParams& p) {
         p.filter.type = ShadowFilter::Vsm, p.key.type = LightType::Spot, p.map.autoFit = false,
         p.map.nearPlane = 1e-5f, p.map.farPlane = 10.0f;
       }),
       "", "", "far/near ratio"},
      {"esm-near-far-ratio-1e6", edit([](ShadowsParams& p) {
         p.filter.type = ShadowFilter::Esm, p.filter.esmExponent = 85.0f, p.key.type = LightType::Spot,
         p.map.autoFit = false, p.map.nearPlane = 1e-5f, p.map.farPlane = 10.0f;
       }),
       "", "", "far/near ratio"},
      {"evsm-near-far-ratio-1e6", edit([](ShadowsParams& p) {
         p.filter.type = ShadowFilter::Evsm, p.filter.evsmPositive = 42.0f, p.filter.evsmNegative = 42.0f,
         p.key.type = LightType::Spot, p.map.autoFit = false, p.map.nearPlane = 1e-5f, p.map.farPlane = 10.0f;
       }),
       "", "", "far/near ratio"},
      {"vsm-near-far-ratio-1e-4", edit([](ShadowsParams& p) {
         p.filter.type = ShadowFilter::Vsm, p.key.type = LightType::Spot, p.map.autoFit = false,
         p.map.nearPlane = 10.0f, p.map.farPlane = 0.001f;
       }),
       "", "", "near plane is beyond"},
      {"esm-near-far-ratio-1e-4", edit([](ShadowsParams& p) {
         p.filter.type = ShadowFilter::Esm, p.map.autoFit = false, p.map.nearPlane = 10.0f, p.map.farPlane = 0.001f;
       }),
       "", "", "near plane is beyond"},
      {"evsm-ortho-huge", edit([](ShadowsParams& p) {
         p.filter.type = ShadowFilter::Evsm, p.map.autoFit = false, p.map.orthoExtent = 1000.0f,
         p.map.nearPlane = 0.001f, p.map.farPlane = 10000.0f;
       }),
       "", "", ""},
      {"vsm-no-blur-no-mips-scale-1e4", edit([](ShadowsParams& p) {
         p.filter.type = ShadowFilter::Vsm, p.filter.blurRadius = 0, p.filter.momentMips = false,
         p.filter.minVariance = 0.0f, p.scene.scale = 10000.0f;
       }),
       "", "", ""},
      {"pcss-point-light-scale-1e6", edit([](ShadowsParams& p) {
         p.filter.type = ShadowFilter::Pcss, p.key.type = LightType::Point, p.key.radius = 0.1f, p.scene.scale = 1e6f;
       }),
       "", "", ""},
      {"vsm-point-light-falls-back",
       edit([](ShadowsParams& p) { p.filter.type = ShadowFilter::Vsm, p.key.type = LightType::Point; }), "", "",
       "point light"},
      // Cascades and view fitting at the edges of what they handle.
      {"cascades-grazing-0.1", edit([](ShadowsParams& p) {
         p.map.fit = MapFit::Cascades, p.key.elevationDeg = 0.1f, p.filter.type = ShadowFilter::Pcss;
       }),
       "", "", "grazing light"},
      {"cascades-scale-1e-3", edit([](ShadowsParams& p) {
         p.map.fit = MapFit::Cascades, p.scene.scale = 0.001f, p.filter.type = ShadowFilter::Evsm;
       }),
       "", "", ""},
      {"view-fit-camera-sees-nothing", edit([](ShadowsParams& p) { p.map.fit = MapFit::View; }), "",
       "yaw=0,pitch=80,distance=5,target=0;300;0", ""},
      {"depth-range-camera-sees-nothing", edit([](ShadowsParams& p) { p.map.fit = MapFit::DepthRange; }), "",
       "yaw=0,pitch=80,distance=5,target=0;300;0", ""},
      {"depth-range-scale-1e4", edit([](ShadowsParams& p) {
         p.map.fit = MapFit::DepthRange, p.scene.scale = 1e4f, p.filter.type = ShadowFilter::Pcss;
       }),
       "learnopengl", "", ""},
      {"cascades-learnopengl-far-100",
       edit([](ShadowsParams& p) { p.map.fit = MapFit::Cascades, p.map.cascadeCount = 4, p.map.splitLambda = 1.0f; }),
       "learnopengl", "", ""},
  };
}

}  // namespace shadelab

namespace shadelab {

std::vector<SceneRecipe> ShadowsLab::scenes() const {
  // The scene of LearnOpenGL's shadow-mapping chapter (learnopengl.com, "Shadow Mapping"), laid out
  // as there so the chapter and the lab can be read side by side: a 50 x 50 floor at y = -0.5,
  // three cubes, the light at (-2, 4, -1) looking at the origin. The camera looks down -z from
  // above and behind, as the chapter's figures do, with its 45 degree field of view, near 0.1 and
  // far 100 (so the floor runs to the horizon: what a whole-scene map wastes texels on).
  return {{"learnopengl", "LearnOpenGL's shadow-mapping scene: a 50x50 floor and three cubes, its light and camera",
           [](Scene& s, const SceneNeeds&) {
             Material floor, cube;
             floor.name = "floor";
             floor.baseColor = glm::vec4(0.72f, 0.7f, 0.66f, 1.0f);
             cube.name = "cube";
             cube.baseColor = glm::vec4(0.85f, 0.55f, 0.35f, 1.0f);
             s.materials = {floor, cube};
             auto add = [&](MeshData mesh, int material, const glm::mat4& model) {
               mesh.material = material;
               s.instances.push_back({int(s.meshes.size()), model});
               s.meshes.push_back(std::move(mesh));
             };
             add(makePlane(50.0f, 1, 25.0f), 0, glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, -0.5f, 0.0f)));
             const glm::mat4 I(1.0f);
             add(makeBox(glm::vec3(0.5f)), 1, glm::translate(I, glm::vec3(0.0f, 1.5f, 0.0f)));
             add(makeBox(glm::vec3(0.5f)), 1, glm::translate(I, glm::vec3(2.0f, 0.0f, 1.0f)));
             add(makeBox(glm::vec3(0.25f)), 1,
                 glm::rotate(glm::translate(I, glm::vec3(-1.0f, 0.0f, 2.0f)), glm::radians(60.0f),
                             glm::normalize(glm::vec3(1.0f, 0.0f, 1.0f))));
             s.suggestedCamera = "yaw=0,pitch=25,distance=7,target=0;0;0.5,fov=45,near=0.1,far=100";
             s.suggestedLight = glm::vec3(-2.0f, 4.0f, -1.0f);
             // The chapter's fixed +-10 box on its 1024^2 map misclassifies 0.085 % of the pixels of
             // this view against ray-traced visibility (3x3 PCF); one map fitted to the scene (a
             // half-extent of 35) 0.31 %, fitted to the view 0.15 %. Four cascades of 512^2, the
             // chapter's memory split four ways, 0.063 %: sharper than the chapter for the least
             // cost among the fits that are (two of 1024^2: 0.053 %, four of 2048^2: 0.034 %, each
             // pass paying for its texels; tutorials/shadows.md, section 10). So the scene opens
             // with those.
             s.suggestedSettings = {"shadows.fit=cascades", "shadows.map_size=512"};
             return std::string();
           }}};
}

}  // namespace shadelab

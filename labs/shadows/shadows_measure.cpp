// The shadows lab against ground truth: ray-traced visibility of the key light (Embree), the
// error numbers, the standard sweep and the stress cases.
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "scene/procedural.h"

#include "labs/shadows/ray_visibility.h"
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
  spec.truth = "ray-traced";
  spec.overrides = {{"filter", "hard"}, {"map_size", "2048"}, {"depth_format", "24"}, {"fit", "scene"},
                    {"bias", "2.5"}, {"slope_bias", "4"}, {"normal_offset", "0"}, {"offset_factor", "0"},
                    {"offset_units", "0"}, {"pcf_size", "3"}, {"receiver_plane", "on"}, {"cull_front", "off"},
                    {"border_clamp", "on"}, {"far_fix", "on"}, {"view", "visibility"}, {"show_frustum", "off"},
                    {"fill_light", "off"}};
  spec.description = "Embree ray-traced visibility of the key light on the same triangles and camera, two truths in "
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

Metrics ShadowsLab::metrics(const ImageF& image, const ImageF& reference) const {
  if (image.size != reference.size)
    return {{"misclassified_pct", 100}, {"visibility_rmse_hard", 1}, {"visibility_rmse_area", 1}, {"acne_pct", 100},
            {"leak_pct", 100}, {"valid_pct", 0}};
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
  return {{"misclassified_pct", 100.0 * wrong / n}, {"visibility_rmse_hard", std::sqrt(hardSq / n)},
          {"visibility_rmse_area", std::sqrt(areaSq / n)}, {"acne_pct", lit > 0 ? 100.0 * acne / lit : 0.0},
          {"leak_pct", shadowed > 0 ? 100.0 * leak / shadowed : 0.0}, {"valid_pct", 100.0 * valid / double(pixels)}};
}

Settings ShadowsLab::metricNotes() const {
  return {{"misclassified_pct", "pixels whose lit/shadowed verdict (visibility >= 0.5) differs from the point-light "
                                "truth's, in % of the pixels that face the key light"},
          {"visibility_rmse_hard", "RMS of (visibility - point-light truth) over the pixels that face the key light"},
          {"visibility_rmse_area", "RMS of (visibility - area-light truth, light_radius) over the same pixels"},
          {"acne_pct", "pixels shadowed by the map (< 0.5) where the point-light truth is fully lit, in % of the "
                       "fully lit pixels"},
          {"leak_pct", "pixels lit by the map (>= 0.5) where the point-light truth is fully shadowed, in % of the "
                       "fully shadowed pixels"},
          {"valid_pct", "pixels that face the key light, in % of the image"}};
}

std::vector<SweepAxis> ShadowsLab::standardSweep() const {
  return {{"filter", {"hard", "hardware-pcf", "pcf:pcf_size=3", "pcf:pcf_size=5", "poisson", "pcss", "vsm", "esm",
                      "evsm"}},
          {"map_size", {"512", "1024", "2048", "4096"}},
          {"bias", {"0:slope_bias=0", "2.5:slope_bias=4"}}};  // no bias at all, and the default
}

std::vector<StressCase> ShadowsLab::stressCases() const {
  return {
      {"grazing-85", {{"light_elevation", "5"}}, "", "", "grazing light"},
      {"grazing-89.9", {{"light_elevation", "0.1"}}, "", "", "grazing light"},
      {"grazing-89.9-pcss", {{"light_elevation", "0.1"}, {"filter", "pcss"}}, "", "", "grazing light"},
      {"point-light-inside-sphere", {{"light_type", "point"}, {"light_distance", "0"}}, "sphere", "", "inside geometry"},
      {"spot-light-inside-scene", {{"light_type", "spot"}, {"light_distance", "0.3"}}, "", "", "inside the scene"},
      {"near-far-ratio-1e4", {{"light_type", "spot"}, {"auto_fit", "off"}, {"near", "0.001"}, {"far", "10"}}, "", "", ""},
      {"near-far-ratio-1e6", {{"light_type", "spot"}, {"auto_fit", "off"}, {"near", "0.00001"}, {"far", "10"}}, "", "",
       "far/near ratio"},
      {"point-near-far-ratio-1e6", {{"light_type", "point"}, {"auto_fit", "off"}, {"near", "0.00001"}, {"far", "10"}},
       "", "", "far/near ratio"},
      {"near-beyond-far", {{"auto_fit", "off"}, {"near", "5"}, {"far", "1"}}, "", "", "near plane is beyond"},
      {"light-radius-0-pcss", {{"filter", "pcss"}, {"light_radius", "0"}}, "", "", "radius 0"},
      {"light-radius-huge-pcss", {{"filter", "pcss"}, {"light_radius", "10"}}, "", "", "larger than the scene"},
      {"ortho-extent-tiny", {{"auto_fit", "off"}, {"ortho_extent", "0.001"}}, "", "", "outside the map"},
      {"ortho-extent-huge", {{"auto_fit", "off"}, {"ortho_extent", "1000"}, {"near", "0.001"}, {"far", "10000"}}, "",
       "", ""},
      {"scene-scale-1e-3", {{"scene_scale", "0.001"}, {"filter", "pcss"}}, "", "", ""},
      {"scene-scale-1e4", {{"scene_scale", "10000"}, {"filter", "pcss"}}, "", "", ""},
      {"point-scale-1e-3", {{"scene_scale", "0.001"}, {"light_type", "point"}}, "", "", ""},
      {"pcss-blocker-at-receiver", {{"filter", "pcss"}, {"bias", "0"}, {"slope_bias", "0"}}, "", "", "no bias"},
      {"point-pcss", {{"light_type", "point"}, {"filter", "pcss"}, {"light_radius", "0.3"}}, "", "", ""},
      {"no-light-casts", {{"key_casts", "off"}}, "", "", "no light casts"},
      {"empty-scene", {{"fill_light", "on"}}, "empty", "", ""},
      {"map-8192-d32f", {{"map_size", "8192"}, {"depth_format", "32f"}, {"filter", "pcf"}, {"pcf_size", "15"}}, "",
       "", ""},
      // Filtered maps: moments of depth in 32-bit float must stay finite however stretched the depth range.
      {"vsm-near-far-ratio-1e6", {{"filter", "vsm"}, {"light_type", "spot"}, {"auto_fit", "off"}, {"near", "0.00001"},
                                  {"far", "10"}}, "", "", "far/near ratio"},
      {"esm-near-far-ratio-1e6", {{"filter", "esm"}, {"esm_exponent", "85"}, {"light_type", "spot"}, {"auto_fit", "off"},
                                  {"near", "0.00001"}, {"far", "10"}}, "", "", "far/near ratio"},
      {"evsm-near-far-ratio-1e6", {{"filter", "evsm"}, {"evsm_positive", "42"}, {"evsm_negative", "42"},
                                   {"light_type", "spot"}, {"auto_fit", "off"}, {"near", "0.00001"}, {"far", "10"}},
       "", "", "far/near ratio"},
      {"vsm-near-far-ratio-1e-4", {{"filter", "vsm"}, {"light_type", "spot"}, {"auto_fit", "off"}, {"near", "10"},
                                   {"far", "0.001"}}, "", "", "near plane is beyond"},
      {"esm-near-far-ratio-1e-4", {{"filter", "esm"}, {"auto_fit", "off"}, {"near", "10"}, {"far", "0.001"}}, "", "",
       "near plane is beyond"},
      {"evsm-ortho-huge", {{"filter", "evsm"}, {"auto_fit", "off"}, {"ortho_extent", "1000"}, {"near", "0.001"},
                           {"far", "10000"}}, "", "", ""},
      {"vsm-no-blur-no-mips-scale-1e4", {{"filter", "vsm"}, {"blur_radius", "0"}, {"moment_mips", "off"},
                                         {"min_variance", "0"}, {"scene_scale", "10000"}}, "", "", ""},
      {"vsm-point-light-falls-back", {{"filter", "vsm"}, {"light_type", "point"}}, "", "", "point light"},
      // Cascades and view fitting at the edges of what they handle.
      {"cascades-grazing-0.1", {{"fit", "cascades"}, {"light_elevation", "0.1"}, {"filter", "pcss"}}, "", "",
       "grazing light"},
      {"cascades-scale-1e-3", {{"fit", "cascades"}, {"scene_scale", "0.001"}, {"filter", "evsm"}}, "", "", ""},
      {"view-fit-camera-sees-nothing", {{"fit", "view"}}, "", "yaw=0,pitch=80,distance=5,target=0;300;0", ""},
      {"cascades-learnopengl-far-100", {{"fit", "cascades"}, {"cascade_count", "4"}, {"split_lambda", "1"}},
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
             return std::string();
           }}};
}

}  // namespace shadelab

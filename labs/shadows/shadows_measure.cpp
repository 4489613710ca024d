// The shadows lab against ground truth: ray-traced visibility of the key light (Embree), the
// error numbers, the standard sweep and the stress cases.
#include <cmath>

#include "labs/shadows/ray_visibility.h"
#include "labs/shadows/shadows_lab.h"

namespace shadelab {

ReferenceSpec ShadowsLab::reference() const {
  // The truth depends on the scene, the camera, the light and (for PCSS) its radius; never on the
  // map, bias or filter. These overrides name the truth's settings, so a sweep traces it once.
  ReferenceSpec spec;
  spec.kind = TruthKind::Image;
  spec.traced = true;
  spec.displayEncoded = false;  // visibility, not colour
  const bool soft = params.filter == ShadowFilter::Pcss;
  spec.truth = soft ? "area light" : "point light";
  spec.overrides = {{"filter", soft ? "pcss" : "hard"}, {"map_size", "2048"}, {"depth_format", "24"},
                    {"bias", "2.5"}, {"slope_bias", "4"}, {"normal_offset", "0"}, {"offset_factor", "0"},
                    {"offset_units", "0"}, {"pcf_size", "3"}, {"receiver_plane", "on"}, {"cull_front", "off"}, {"border_clamp", "on"},
                    {"far_fix", "on"}, {"view", "visibility"}, {"show_frustum", "off"}, {"fill_light", "off"}};
  if (!soft) spec.overrides.push_back({"light_radius", "0"});
  spec.description = "Embree ray-traced visibility of the key light on the same triangles and camera: one ray per "
                     "pixel for a hard light; for PCSS, 8x8 stratified rays over a disk of the light's radius";
  return spec;
}

TraceWork ShadowsLab::traceReference(Frame& frame) {
  if (!rayScene_ || rayRevision_ != frame.scene.revision) {
    rayScene_ = std::make_shared<const RayScene>(frame.scene);
    rayRevision_ = frame.scene.revision;
  }
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
  LightFrame key = buildLight(keySetup(), bounds, ignored);
  const bool soft = params.filter == ShadowFilter::Pcss && key.radiusWorld > 0.0f;
  if (!soft) key.radiusWorld = 0.0f;
  const float epsilon = 2e-4f * bounds.radius();  // lifts ray origins off the surface they start on
  // The rays are the slow part (seconds for an area light): a job, which owns all it reads.
  return [scene = rayScene_, key, positions = std::move(positions), normals = std::move(normals), soft,
          epsilon](JobContext& job) {
    return rayTracedVisibility(*scene, key, positions, normals, soft ? 8 : 1, epsilon, &job);
  };
}

Metrics ShadowsLab::metrics(const ImageF& image, const ImageF& reference) const {
  if (image.size != reference.size)
    return {{"misclassified_pct", 100}, {"visibility_rmse", 1}, {"acne_pct", 100}, {"leak_pct", 100}, {"valid_pct", 0}};
  double valid = 0, wrong = 0, squared = 0, acne = 0, leak = 0;
  const size_t pixels = size_t(image.size.x) * image.size.y;
  for (size_t i = 0; i < pixels; ++i) {
    // Only surfaces that face the key light (and lie in a spot's cone) have a shadow question.
    if (image.rgba[i * 4 + 3] < 0.5f || reference.rgba[i * 4 + 3] < 0.5f) continue;
    const double v = image.rgba[i * 4], r = reference.rgba[i * 4];
    valid += 1;
    wrong += (v >= 0.5) != (r >= 0.5);
    squared += (v - r) * (v - r);
    acne += r >= 0.99 && v < 0.5;  // fully lit in truth, shadowed by the map: acne (or a blur spilling over)
    leak += r <= 0.01 && v >= 0.5;  // fully shadowed in truth, lit by the map: peter-panning, light leaks
  }
  const double n = std::max(valid, 1.0);
  return {{"misclassified_pct", 100.0 * wrong / n}, {"visibility_rmse", std::sqrt(squared / n)},
          {"acne_pct", 100.0 * acne / n}, {"leak_pct", 100.0 * leak / n}, {"valid_pct", 100.0 * valid / double(pixels)}};
}

std::vector<SweepAxis> ShadowsLab::standardSweep() const {
  return {{"filter", {"hard", "hardware-pcf", "pcf:pcf_size=3", "pcf:pcf_size=5", "poisson", "pcss"}},
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
  };
}

}  // namespace shadelab

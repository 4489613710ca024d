// Ground-truth visibility by ray tracing the same triangles (Embree on the desktop, the GPU
// tracer's BVH on the CPU in the browser: ray_scene_desktop.cpp, ray_scene_web.cpp): no depth map, no bias,
// no resolution. A hard light gets one shadow ray per pixel; an area light (disk or cone of the
// light's radius) gets n x n stratified rays, and visibility is the fraction that get through.
#pragma once
#include <memory>

#include "app/measure/image.h"
#include "app/scene/scene.h"
#include "app/util/job_runner.h"
#include "labs/shadows/light_rig.h"

namespace shadelab {

class RayScene {
 public:
  explicit RayScene(const Scene& scene);  // every instance, in world space
  ~RayScene();
  RayScene(const RayScene&) = delete;
  RayScene& operator=(const RayScene&) = delete;
  // True when something lies between origin and origin + dir * maxDistance (dir need not be unit).
  bool occluded(const glm::vec3& origin, const glm::vec3& dir, float maxDistance) const;
  size_t triangleCount() const { return triangles_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  size_t triangles_ = 0;
};

// The centre of cell (i, j) of an n x n grid mapped into the unit disk (Shirley and Chiu's
// concentric map): the area light's stratified samples, the same for Embree and the GPU tracer.
glm::vec2 stratifiedDiskSample(int i, int j, int n);

// positions: xyz = world position, w > 0.5 where a surface was drawn that faces the light;
// normals: xyz = its normal. Returns the visibility of the light's centre (a point light: one
// ray) in R, of its whole disk (samplesPerAxis^2 stratified rays; the centre's again when the
// radius is 0) in G and B, and the same validity in A.
// `epsilon` (world units) lifts ray origins off the surface along the normal. With a `job`, rows
// report progress and stop early when it is cancelled (the image is then incomplete).
ImageF rayTracedVisibility(const RayScene& scene, const LightFrame& light, const ImageF& positions,
                           const ImageF& normals, int samplesPerAxis, float epsilon, JobContext* job = nullptr);

}  // namespace shadelab

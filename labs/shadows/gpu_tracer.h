// The shadows lab's truth on the GPU: the same question as Embree's (is the key light's centre
// visible from this pixel's surface, and what fraction of its disk), asked by a fragment shader
// that walks a BVH of the scene's triangles (shaders/shadows/trace.frag). One pass adds one
// sample of the disk to every pixel (the first), then up to sixteen, so the area truth converges pass
// by pass, in the window between frames, while its standard error shrinks; after samplesPerAxis^2
// samples it is the Embree truth's estimator, sample for sample. Needs no Embree: the browser's
// truth too.
#pragma once
#include <memory>
#include <optional>

#include "gl/texture.h"
#include "labs/shadows/light_rig.h"
#include "measure/bvh.h"
#include "measure/image.h"
#include "scene/scene.h"
#include "shader/shader_library.h"

namespace shadelab {

// Every instance's triangles in world space: what the tracer (and Embree's RayScene) trace.
std::vector<BvhTriangle> sceneTriangles(const Scene& scene);

class GpuShadowTracer {
 public:
  // The BVH of the scene's triangles, built and uploaded when the scene's revision changes.
  void prepare(const Scene& scene);
  // A new accumulation over `positions`/`normals` (the lab's g-buffer, RGBA32F, as the Embree
  // truth reads them) for `light`: samplesPerAxis^2 disk samples (1 when the light has no radius).
  void begin(gl::RenderTarget positions, gl::RenderTarget normals, const LightFrame& light, int samplesPerAxis,
             float epsilon);
  // A band of rows of the current pass, sized to take about `budgetMs` (the GPU finishes it
  // before this returns: a driver that defers its work, as llvmpipe does, would otherwise queue
  // every pass into one frame). Returns false once every sample of every pixel is in.
  bool step(ShaderLibrary& shaders, ProgramSlot& program, double budgetMs = 25.0);
  int samplesDone() const { return pass_; }  // disk samples in every pixel so far
  int samplesWanted() const { return samples_; }
  // R the hard truth, G = B the mean of the area samples so far, A coverage: the Embree truth's
  // layout. `standardError`, if given, receives the mean standard error of G over covered pixels.
  ImageF result(double* standardError = nullptr) const;
  size_t triangleCount() const { return bvh_ ? bvh_->triangles().size() : 0; }
  // Pixels where a ray visited more nodes than the tree has (as of the last result()): a broken
  // tree or driver; the traversal stops there instead of hanging, and the lab says so.
  size_t gaveUp() const { return gaveUp_; }
  // The tracer's program; `oneRay` for a light of no size, whose passes trace the hard ray alone
  // (ONE_RAY: the walk's loops over a pass's rays fold away).
  static ProgramSpec programSpec(bool oneRay);

 private:
  int revision_ = -1;
  std::shared_ptr<const Bvh> bvh_;
  gl::Texture2D nodes_, triangles_;
  int nodeCount_ = 0;  // in the walk's order (Bvh::nodeTexels)
  std::optional<gl::RenderTarget> positions_, normals_, sum_;
  gl::VertexArray vao_;
  LightFrame light_;
  int perAxis_ = 1, samples_ = 1, pass_ = 0;
  int bandStart_ = 0;        // the next band of the current pass
  int bandRowSamples_ = 16;  // its height times the pass's samples: what fits the budget
  float epsilon_ = 0.0f;
  mutable size_t gaveUp_ = 0;
};

}  // namespace shadelab

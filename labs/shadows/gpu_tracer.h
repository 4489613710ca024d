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

#include "app/gl/texture.h"
#include "app/measure/bvh.h"
#include "app/measure/image.h"
#include "app/scene/scene.h"
#include "app/shader/shader_library.h"
#include "labs/shadows/light_rig.h"

namespace shadelab {

// Every instance's triangles in world space: what the tracer (and Embree's RayScene) trace.
std::vector<BvhTriangle> sceneTriangles(const Scene& scene);

// How the GPU tracer cuts its work: disk samples a draw after the first (up to 16, trace.frag's
// u_disks), rays that walk the BVH together (trace.frag's WALK_WIDTH) and triangles a leaf of the
// BVH. More samples a draw add into the float target fewer times; wider walks read each node for
// more rays, and hold more of them in registers; smaller leaves test fewer triangles and more
// boxes. A cone around a walk's rays (trace.frag's CONE_CULL) turns a node away for all of them
// with one test. BM_GpuTruthShape measures each on the machine at hand.
struct GpuTraceShape {
  int samplesPerDraw = 16;
  int walkWidth = 8;
  int leafSize = 2;
  bool coneCull = true;
};

class GpuShadowTracer {
 public:
  using Shape = GpuTraceShape;
  static constexpr int kMaxSamplesPerDraw = 16;

  explicit GpuShadowTracer(Shape shape = {});
  Shape shape() const { return shape_; }

  // The BVH of the scene's triangles, built and uploaded when the scene's revision changes.
  void prepare(const Scene& scene);
  // The g-buffer the next trace reads, for the lab to draw at `size`: RGBA32F positions and
  // normals, as the Embree truth reads them. The tracer's targets are kept from one trace to the
  // next of the same size (a GPU allocates, and a driver clears, fresh ones at a cost).
  const gl::RenderTarget& positions(glm::ivec2 size);
  const gl::RenderTarget& normals(glm::ivec2 size);
  // A new accumulation over the g-buffer for `light`: samplesPerAxis^2 disk samples (1 when the
  // light has no radius; 15^2 at most, so that a pixel's count fits the read-back's byte).
  void begin(const LightFrame& light, int samplesPerAxis, float epsilon);
  // The programs it draws with, kept by the lab that owns the shader library.
  struct Programs {
    ProgramSlot trace, resolve;
    void reset() {
      trace.reset();
      resolve.reset();
    }
  };
  // A band of rows of the current pass, sized to take about `budgetMs` (the GPU finishes it
  // before this returns: a driver that defers its work, as llvmpipe does, would otherwise queue
  // every pass into one frame). Returns false once every sample of every pixel is in.
  bool step(ShaderLibrary& shaders, Programs& programs, double budgetMs = 25.0);
  int samplesDone() const { return pass_; }  // disk samples in every pixel so far
  int samplesWanted() const { return samples_; }
  // R the hard truth, G = B the mean of the area samples so far, A coverage: the Embree truth's
  // layout. `standardError`, if given, receives the mean standard error of G over covered pixels.
  // The sums are packed into bytes on the GPU first (trace_resolve.frag): a quarter of the read.
  ImageF result(ShaderLibrary& shaders, Programs& programs, double* standardError = nullptr);
  size_t triangleCount() const { return bvh_ ? bvh_->triangles().size() : 0; }
  // Pixels where a ray visited more nodes than the tree has (as of the last result()): a broken
  // tree or driver; the traversal stops there instead of hanging, and the lab says so.
  size_t gaveUp() const { return gaveUp_; }
  // Milliseconds spent in step() since begin(), the waits for the GPU included: the trace alone,
  // without the g-buffer before it or the read-back after it.
  double traceMs() const { return traceMs_; }
  // The tracer's program; `oneRay` for a light of no size, whose passes trace the hard ray alone
  // (ONE_RAY: a walk of one ray).
  static ProgramSpec programSpec(bool oneRay, const GpuTraceShape& shape = {});
  static ProgramSpec resolveSpec();

 private:
  Shape shape_;
  int revision_ = -1;
  std::shared_ptr<const Bvh> bvh_;
  gl::Texture2D nodes_, triangles_;
  int nodeCount_ = 0;  // in the walk's order (Bvh::nodeTexels)
  std::optional<gl::RenderTarget> positions_, normals_, sum_, packed_;
  gl::VertexArray vao_;
  LightFrame light_;
  int perAxis_ = 1, samples_ = 1, pass_ = 0;
  int bandStart_ = 0;        // the next band of the current pass
  int bandRowSamples_ = 16;  // its height times the pass's samples: what fits the budget
  float epsilon_ = 0.0f;
  double traceMs_ = 0.0;
  size_t gaveUp_ = 0;
};

}  // namespace shadelab

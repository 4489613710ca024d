// The denoising lab's steps on the GPU (gpu_smoother.h): which configurations take them, the
// smoother's mesh and input kept up to date, and the mesh drawn from its texture meanwhile.
#include "labs/denoise/denoise_lab.h"

namespace shadelab {

bool DenoiseLab::smoothsOnGpu(const DenoiseConfig& c) const {
  return c.device == SmoothingDevice::Gpu && gpuUnavailable_.empty() && methodRow(c.smoothing.method).onGpu;
}

SmoothedElsewhere DenoiseLab::smoothOnGpu(const DenoiseConfig& c) {
  // The mesh and the noisy input go up once each: a lambda or iterations drag changes neither.
  const GpuInput input{modelRevision_, c.weld, c.publishedInput, c.noise};
  if (!gpuInput_ || !(*gpuInput_ == input)) {
    SmoothingInput in = smoothingInput(*model_, c);
    if (!gpuInput_ || gpuInput_->model != input.model || gpuInput_->weld != input.weld) {
      gpu_.setMesh(in.start.size(), in.indices, *in.adjacency);
      // Each render vertex is drawn from the texel of the vertex it is smoothed as (its welded
      // vertex, or itself without weld): SMOOTHED_ON_GPU in mesh.vert.
      std::vector<float> texel(model_->render.positions.size());
      for (size_t v = 0; v < texel.size(); ++v) texel[v] = float(c.weld ? model_->welded.logicalOf[v] : uint32_t(v));
      plainMesh_.setScalars(kScalar0, texel);  // exact: a float holds every index below 2^24
    }
    gpu_.setStart(in.start);
    gpuInput_ = input;
  }
  const GpuSmoothing run = gpu_.run(*shaders_, c.smoothing);
  gpuDrawn_ = true;  // drawn from the smoother's texture until the job's result arrives
  return {gpu_.readPositions(), run.energy, run.grewAt, run.stoppedAt, run.ms};
}

}  // namespace shadelab

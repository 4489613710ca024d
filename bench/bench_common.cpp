#include "bench_common.h"

#include <cstdio>
#include <cstdlib>
#include <memory>

#include "app/context/gl_context.h"
#include "app/util/process_memory.h"

namespace shadelab {

void timeFrames(benchmark::State& state, LabHost& host, glm::ivec2 size) {
  for (int i = 0; i < 2; ++i) host.renderFrame(size);
  for (auto _ : state) {
    double gpu = 0;
    for (auto& pass : host.renderFrame(size)) gpu += pass.gpuMs;
    state.SetIterationTime(gpu / 1000.0);
  }
}

void timeConfiguration(benchmark::State& state, const char* lab, const std::vector<std::string>& config,
                       const std::vector<std::string>& extra) {
  LabHost host(ShaderSearchPath({builtinShaderDir()}));
  host.selectLab(lab);
  std::string label;
  for (const std::string& kv : extra) host.set(std::string(lab) + "." + kv);
  for (const std::string& kv : config) {
    host.set(std::string(lab) + "." + kv);
    label += (label.empty() ? "" : " ") + kv;
  }
  timeFrames(state, host, {1280, 720});
  state.SetLabel(label);
}

void depthMapSampling(unsigned target) {
  glTexParameteri(target, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(target, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(target, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
  glTexParameteri(target, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
  const float white[4] = {1, 1, 1, 1};
  glTexParameterfv(target, GL_TEXTURE_BORDER_COLOR, white);
}

}  // namespace shadelab

using namespace shadelab;

int main(int argc, char** argv) {
  keepLargeBlocksApart();  // the allocator as the application sets it
  benchmark::Initialize(&argc, argv);
  const char* backend = std::getenv("SHADELAB_BACKEND");
  std::string err;
  std::unique_ptr<GlContext> context = createHeadlessContext(backend ? backend : "osmesa", err);
  if (!context) {
    std::fprintf(stderr, "shadelab_bench: %s\n", err.c_str());
    return 1;
  }
  std::fprintf(stderr, "renderer: %s\n", context->describe().c_str());
  benchmark::RunSpecifiedBenchmarks();
  context.reset();
  return 0;
}

// The denoising lab's frame, idle and while a job runs (below). Its CPU work beside OpenMesh's is
// denoise_bench.cpp, a program of its own.
#include <benchmark/benchmark.h>

#include <chrono>

#include "bench_common.h"

using namespace shadelab;

namespace {

// BM_DenoiseFrame/<busy>: the wall time of one window-sized frame of the denoising lab on the Bunny
// (69,451 triangles), idle (0) and while a smoothing job runs on the worker (1). The frame is what
// the UI thread pays: deliveries, uploads and the draw. The bound: busy within 2x idle.
void BM_DenoiseFrame(benchmark::State& state) {
  LabHost host(ShaderSearchPath({builtinShaderDir()}));
  host.selectLab("denoise");
  if (!host.selectScene("bunny-0.2").empty()) {
    state.SkipWithError("bunny-0.2 needs ../shared/data");
    return;
  }
  host.jobs().setLowPriority(true);      // as in the window
  host.set("denoise.method=bilateral");  // about 0.5 s per job on the Bunny: long enough to overlap frames
  host.settle();
  const glm::ivec2 size(900, 780);
  for (int i = 0; i < 3; ++i) host.renderFrame(size);
  const bool busy = state.range(0) == 1;
  int jobs = 0;
  for (auto _ : state) {
    if (busy && !host.jobs().busy()) {
      host.runAction("denoise.add_noise");  // new noise, a new job
      host.renderFrame(size);               // submits it (untimed)
      ++jobs;
    }
    const auto t0 = std::chrono::steady_clock::now();
    host.renderFrame(size);
    state.SetIterationTime(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  host.jobs().cancelAll();
  state.SetLabel(busy ? "while a job runs (" + std::to_string(jobs) + " jobs)" : "idle");
}
BENCHMARK(BM_DenoiseFrame)->Arg(0)->Arg(1)->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(40);

}  // namespace

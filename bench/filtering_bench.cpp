// The filtering lab. BM_FilteringFilter: per filter on its grazing plane; BM_FilteringReference: its
// supersampled truth for one frame (below).
#include <benchmark/benchmark.h>

#include <chrono>

#include "bench_common.h"

using namespace shadelab;

namespace {

// BM_FilteringFilter/<i>: GPU ms of a 1280x720 frame of the filtering lab's grazing plane per
// filter, without the footprint probe (the sweep's configurations).
const std::vector<std::vector<std::string>> kFilteringConfigs = {
    {"filter=nearest", "mipmaps=off"},
    {"filter=bilinear", "mipmaps=off"},
    {"filter=bilinear", "mipmaps=off", "in_shader=on"},
    {"filter=bicubic", "mipmaps=off"},
    {"filter=nearest", "mipmaps=nearest-level"},
    {"filter=bilinear", "mipmaps=nearest-level"},
    {"filter=bilinear", "mipmaps=linear-level"},
    {"filter=bilinear", "mipmaps=linear-level", "in_shader=on"},
    {"filter=bicubic", "mipmaps=linear-level"},
    {"anisotropy=2"},
    {"anisotropy=4"},
    {"anisotropy=8"},
    {"anisotropy=16"},
    {"anisotropy=16", "in_shader=on"},
};

void BM_FilteringFilter(benchmark::State& state) {
  timeConfiguration(state, "filtering", kFilteringConfigs[size_t(state.range(0))], {"footprint_probe=off"});
}
BENCHMARK(BM_FilteringFilter)
    ->DenseRange(0, int(kFilteringConfigs.size()) - 1)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(10);

// BM_FilteringReference: wall seconds of the supersampled truth of one 1280x720 frame of the
// grazing plane (16 x 16 jittered frames; the bound is 60 s on llvmpipe).
void BM_FilteringReference(benchmark::State& state) {
  LabHost host(ShaderSearchPath({builtinShaderDir()}));
  host.selectLab("filtering");
  host.renderFrame({1280, 720});
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    const ImageF truth = host.renderReference({1280, 720});
    benchmark::DoNotOptimize(truth.rgba.data());
    state.SetIterationTime(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
}
BENCHMARK(BM_FilteringReference)->UseManualTime()->Unit(benchmark::kSecond)->Iterations(1);

}  // namespace

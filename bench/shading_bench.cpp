// The shading lab. BM_Frame/<mode>: one 1280x720 frame of its default scene, per shading mode.
#include <benchmark/benchmark.h>

#include "bench_common.h"

using namespace shadelab;

namespace {

void BM_Frame(benchmark::State& state) {
  static const char* modes[] = {"flat", "gouraud", "phong"};
  LabHost host(ShaderSearchPath({builtinShaderDir()}));
  host.set(std::string("shading.mode=") + modes[state.range(0)]);
  timeFrames(state, host, {1280, 720});
  state.SetLabel(modes[state.range(0)]);
}
BENCHMARK(BM_Frame)->DenseRange(0, 2)->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(20);

}  // namespace

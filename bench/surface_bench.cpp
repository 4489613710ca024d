// The surface lab. BM_SurfaceTechnique: per technique and its cost knob (below).
#include <benchmark/benchmark.h>

#include "bench_common.h"

using namespace shadelab;

namespace {

// BM_SurfaceTechnique/<i>: GPU ms of a 1280x720 frame of the surface lab's brick wall, per technique
// and its cost knob (layers, subdivision, tessellation level): the sweep's configurations and every
// technique's default (subdivision 6, tessellation level 16, 16 layers).
const std::vector<std::vector<std::string>> kSurfaceConfigs = {
    {"technique=none"},
    {"technique=normal-map"},
    {"technique=bump"},
    {"technique=displacement", "subdivision=3"},
    {"technique=displacement", "subdivision=5"},
    {"technique=displacement", "subdivision=6"},
    {"technique=displacement", "subdivision=7"},
    {"technique=tessellation", "tess_level=4"},
    {"technique=tessellation", "tess_level=16"},
    {"technique=tessellation", "tess_level=64"},
    {"technique=parallax"},
    {"technique=steep-parallax", "layers=8"},
    {"technique=steep-parallax", "layers=16"},
    {"technique=steep-parallax", "layers=32"},
    {"technique=pom", "layers=4"},
    {"technique=pom", "layers=8"},
    {"technique=pom", "layers=16"},
    {"technique=pom", "layers=32"},
    {"technique=pom", "layers=64"},
    {"technique=pom", "layers=16", "self_shadow=on"},
};

void BM_SurfaceTechnique(benchmark::State& state) {
  timeConfiguration(state, "surface", kSurfaceConfigs[size_t(state.range(0))]);
}
BENCHMARK(BM_SurfaceTechnique)
    ->DenseRange(0, int(kSurfaceConfigs.size()) - 1)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(10);

}  // namespace

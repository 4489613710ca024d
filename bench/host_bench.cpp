// The host's own costs. Run: build/bench/shadelab_bench --benchmark_filter='ReloadLatency|CompileProgram'
//
// BM_ReloadLatency: a student saves shade.frag; how long until the first frame drawn with the new
// program? Measured from just before the write to the end of the first frame whose program build
// count went up, through the real path: inotify -> debounce -> preprocess -> compile -> link -> draw.
// BM_CompileProgram: the compile + link part of that, for one program.
// BM_ImageBuffer/<huge pages>: a 1280x720 RGBA float buffer allocated and filled, as a read-back
// or a truth is, with the allocator as the application sets it (keepLargeBlocksApart): a plain
// vector (0) or largeBuffer, which asks for huge pages (1).
#include <benchmark/benchmark.h>

#include <unistd.h>

#include <chrono>
#include <fstream>

#include "app/util/process_memory.h"
#include "app/util/read_file.h"
#include "bench_common.h"

namespace fs = std::filesystem;
using namespace shadelab;

namespace {

void BM_ReloadLatency(benchmark::State& state) {
  const fs::path builtin = builtinShaderDir();
  const fs::path student = fs::temp_directory_path() / ("shadelab_bench_" + std::to_string(::getpid()));
  fs::create_directories(student / "shading");
  const fs::path frag = student / "shading" / "shade.frag";
  const std::string original = readWholeFile(builtin / "shading" / "shade.frag");
  std::ofstream(frag) << original;
  LabHost host(ShaderSearchPath({student, builtin}));
  const glm::ivec2 size(640, 360);
  host.renderFrame(size);
  int edit = 0;
  for (auto _ : state) {
    const Program& p = *host.lab().activePrograms().front();
    const int generation = p.generation();
    const auto start = std::chrono::steady_clock::now();
    std::ofstream(frag, std::ios::trunc) << original << "\n// edit " << ++edit << "\n";  // new content each time
    while (p.generation() == generation) host.renderFrame(size);
    state.SetIterationTime(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  fs::remove_all(student);
}
BENCHMARK(BM_ReloadLatency)->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(15);

// The compile + link share of the reload: one program of the shading lab, rebuilt from disk.
void BM_CompileProgram(benchmark::State& state) {
  LabHost host(ShaderSearchPath({builtinShaderDir()}));
  host.renderFrame({64, 64});
  Program& p = *host.lab().activePrograms().front();
  for (auto _ : state) host.shaders().rebuild(p, /*force=*/true);
}
BENCHMARK(BM_CompileProgram)->Unit(benchmark::kMillisecond)->Iterations(10);

void BM_ImageBuffer(benchmark::State& state) {
  const size_t count = size_t(1280) * 720 * 4;
  for (auto _ : state) {
    std::vector<float> image = state.range(0) ? largeBuffer<float>(count) : std::vector<float>(count);
    for (size_t i = 0; i < count; i += 4) image[i] = float(i);
    benchmark::DoNotOptimize(image.data());
  }
  state.SetLabel(state.range(0) ? "largeBuffer (huge pages asked for)" : "std::vector");
}
BENCHMARK(BM_ImageBuffer)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly(true);

}  // namespace

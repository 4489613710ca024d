// The denoising lab's CPU work, and a peer beside it. Run: build/bench/shadelab_denoise_bench
//
// BM_Explicit/<iterations>: our explicit Laplacian step on the Bunny (34,834 vertices), uniform
//   weights, full umbrella vector, lambda 0.5, including the energy bookkeeping the lab reports.
// BM_OpenMesh/<iterations>: OpenMesh's JacobiLaplaceSmootherT on the same mesh, the same update
//   (uniform weights: Tangential_and_Normal, C0; its damping is 0.5). Weights computed in
//   initialize(), outside the timed loop. Compare the two at equal iterations, in one run.
// BM_ExplicitAlongNormal: the lab's default, normals recomputed every iteration.
// BM_Implicit: factorisation + one solve on the Bunny (the lab's iterations reuse the factor).
// BM_Bake/<method>/<resolution>: Spot's offsets into a map (nearest-exact = 0, nearest-approx
//   with 32 checks = 1, raster = 2).
// BM_Steps/<device>/<mesh>: 100 explicit steps along the normal (the lab's default, uniform
//   weights), on the CPU (0) or the GPU (1, gpu_smoother.h: the steps and their divergence checks,
//   to the last step's glFinish), on the Bunny (0) or the Bunny with every edge cut in five (1,
//   about 870,000 vertices). The GPU is the headless context's: SHADELAB_BACKEND=osmesa (default,
//   llvmpipe) or egl (a GPU where the machine has one). Counter steps_per_s.
#include <benchmark/benchmark.h>

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Smoother/JacobiLaplaceSmootherT.hh>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>

#include "app/context/gl_context.h"
#include "app/scene/loaders.h"
#include "app/scene/scene_catalog.h"
#include "labs/denoise/denoise_pipeline.h"
#include "labs/denoise/gpu_smoother.h"
#include "labs/surface/subdivide.h"

using namespace shadelab;

namespace {

struct Loaded {
  WeldedMesh welded;
  Adjacency adjacency;
  std::vector<glm::dvec3> positions;
  MeshData render;
};

const Loaded& mesh(const char* relPath) {
  static std::map<std::string, Loaded> cache;
  auto it = cache.find(relPath);
  if (it != cache.end()) return it->second;
  Scene s;
  if (auto err = loadObj(dataDirectory() / relPath, s); !err.empty()) {
    std::fprintf(stderr, "%s\n", err.c_str());
    std::exit(1);
  }
  Loaded l;
  l.render = s.meshes.front();
  l.welded = weldByPosition(l.render);
  l.adjacency = buildAdjacency(l.welded.vertexCount(), l.welded.indices);
  l.positions.assign(l.welded.positions.begin(), l.welded.positions.end());
  return cache.emplace(relPath, std::move(l)).first->second;
}

const char* kBunny = "denoise/guided_zhang2015/Bunny0.2/Noisy.obj";

// The Bunny, or the Bunny with every edge cut in `parts` (welded: the cuts share their points).
const Loaded& bunny(int parts) {
  static std::map<int, Loaded> cache;
  if (auto it = cache.find(parts); it != cache.end()) return it->second;
  const Loaded& base = mesh(kBunny);
  Loaded l;
  l.render = parts > 1 ? splitEdges(base.render, parts) : base.render;
  l.welded = weldByPosition(l.render);
  l.adjacency = buildAdjacency(l.welded.vertexCount(), l.welded.indices);
  l.positions.assign(l.welded.positions.begin(), l.welded.positions.end());
  return cache.emplace(parts, std::move(l)).first->second;
}

void BM_Explicit(benchmark::State& state) {
  const Loaded& m = mesh(kBunny);
  SmoothingSettings s;
  s.alongNormal = false;
  s.lambda = 0.5;
  s.iterations = int(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(smooth(m.positions, m.welded.indices, m.adjacency, s));
  state.SetLabel(std::to_string(m.positions.size()) + " vertices");
}
BENCHMARK(BM_Explicit)->Arg(1)->Arg(10)->Unit(benchmark::kMillisecond);

void BM_OpenMesh(benchmark::State& state) {
  using Mesh = OpenMesh::TriMesh_ArrayKernelT<>;
  const Loaded& m = mesh(kBunny);
  Mesh om;
  std::vector<Mesh::VertexHandle> handles;
  for (auto& p : m.positions) handles.push_back(om.add_vertex(Mesh::Point(float(p.x), float(p.y), float(p.z))));
  for (size_t t = 0; t + 2 < m.welded.indices.size(); t += 3)
    om.add_face(handles[m.welded.indices[t]], handles[m.welded.indices[t + 1]], handles[m.welded.indices[t + 2]]);
  om.request_vertex_normals();
  om.request_face_normals();
  om.update_normals();
  OpenMesh::Smoother::JacobiLaplaceSmootherT<Mesh> smoother(om);
  smoother.initialize(OpenMesh::Smoother::SmootherT<Mesh>::Tangential_and_Normal,
                      OpenMesh::Smoother::SmootherT<Mesh>::C0);
  for (auto _ : state) smoother.smooth(unsigned(state.range(0)));
  state.SetLabel(std::to_string(om.n_vertices()) + " vertices");
}
BENCHMARK(BM_OpenMesh)->Arg(1)->Arg(10)->Unit(benchmark::kMillisecond);

void BM_ExplicitAlongNormal(benchmark::State& state) {
  const Loaded& m = mesh(kBunny);
  SmoothingSettings s;
  s.iterations = 10;
  for (auto _ : state) benchmark::DoNotOptimize(smooth(m.positions, m.welded.indices, m.adjacency, s));
}
BENCHMARK(BM_ExplicitAlongNormal)->Unit(benchmark::kMillisecond);

void BM_Implicit(benchmark::State& state) {
  const Loaded& m = mesh(kBunny);
  SmoothingSettings s;
  s.method = SmoothingMethod::Implicit;
  s.lambda = 1.0;
  s.iterations = 1;
  for (auto _ : state) benchmark::DoNotOptimize(smooth(m.positions, m.welded.indices, m.adjacency, s));
}
BENCHMARK(BM_Implicit)->Unit(benchmark::kMillisecond);

void BM_Bake(benchmark::State& state) {
  static const char* names[] = {"nearest-exact", "nearest-approx (32 checks)", "raster"};
  const Loaded& m = mesh("meshes/spot_pytorch3d/cow.obj");
  std::vector<float> offsets(m.render.positions.size());
  for (size_t v = 0; v < offsets.size(); ++v) offsets[v] = 0.01f * std::sin(float(v));
  // As the lab bakes it: Spot's UVs leave [0, 1], so its map repeats.
  const BakeSettings s{BakeMethod(state.range(0)),      int(state.range(1)), 32, 4, MapFormat::Unorm16,
                       uvsLeaveUnitSquare(m.render.uvs)};
  for (auto _ : state) {
    const BakeResult r = bakeDisplacement(m.render.uvs, m.render.indices, offsets, s);
    state.SetIterationTime(r.ms / 1000.0);  // the bake's own time, not the approximate one's accuracy check after it
  }
  state.SetLabel(names[state.range(0)]);
}
BENCHMARK(BM_Bake)
    ->ArgsProduct({{0, 1, 2}, {1024}})
    ->Args({0, 4096})
    ->Args({2, 4096})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);

void BM_Steps(benchmark::State& state) {
  const bool gpu = state.range(0) == 1;
  const Loaded& m = bunny(state.range(1) == 1 ? 5 : 1);
  SmoothingSettings s;
  s.iterations = 100;
  std::unique_ptr<GpuSmoother> smoother;
  std::unique_ptr<ShaderLibrary> shaders;
  if (gpu) {
    shaders =
        std::make_unique<ShaderLibrary>(ShaderSearchPath({std::filesystem::path(SHADELAB_SOURCE_DIR) / "shaders"}));
    smoother = std::make_unique<GpuSmoother>();
    smoother->setMesh(m.positions.size(), m.welded.indices, m.adjacency);
    smoother->setStart(m.positions);  // once: a lambda drag starts from the same input
    smoother->run(*shaders, s);       // compiles its programs, outside the timed loop
  }
  for (auto _ : state) {
    if (gpu) {
      state.SetIterationTime(smoother->run(*shaders, s).ms / 1000.0);
    } else {
      const auto t0 = std::chrono::steady_clock::now();
      benchmark::DoNotOptimize(smooth(m.positions, m.welded.indices, m.adjacency, s));
      state.SetIterationTime(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    }
  }
  state.counters["steps_per_s"] =
      benchmark::Counter(double(s.iterations) * double(state.iterations()), benchmark::Counter::kIsRate);
  state.SetLabel(std::string(gpu ? "gpu" : "cpu") + ", " + std::to_string(m.positions.size()) + " vertices");
}
BENCHMARK(BM_Steps)->ArgsProduct({{0, 1}, {0, 1}})->UseManualTime()->Unit(benchmark::kMillisecond);

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  const char* backend = std::getenv("SHADELAB_BACKEND");
  std::string err;
  std::unique_ptr<GlContext> context = createHeadlessContext(backend ? backend : "osmesa", err);
  if (!context) {
    std::fprintf(stderr, "shadelab_denoise_bench: %s (BM_Steps/1/* need it)\n", err.c_str());
    return 1;
  }
  std::fprintf(stderr, "renderer: %s\n", context->describe().c_str());
  benchmark::RunSpecifiedBenchmarks();
  return 0;
}

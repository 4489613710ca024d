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
#include <benchmark/benchmark.h>

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Smoother/JacobiLaplaceSmootherT.hh>

#include <cstdio>

#include "labs/denoise/denoise_pipeline.h"
#include "scene/loaders.h"
#include "scene/scene_catalog.h"

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
  smoother.initialize(OpenMesh::Smoother::SmootherT<Mesh>::Tangential_and_Normal, OpenMesh::Smoother::SmootherT<Mesh>::C0);
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
  const BakeSettings s{BakeMethod(state.range(0)), int(state.range(1)), 32, 4, MapFormat::Unorm16,
                       uvsLeaveUnitSquare(m.render.uvs)};
  for (auto _ : state) {
    const BakeResult r = bakeDisplacement(m.render.uvs, m.render.indices, offsets, s);
    state.SetIterationTime(r.ms / 1000.0);  // the bake's own time, not the approximate one's accuracy check after it
  }
  state.SetLabel(names[state.range(0)]);
}
BENCHMARK(BM_Bake)->ArgsProduct({{0, 1, 2}, {1024}})->Args({0, 4096})->Args({2, 4096})->UseManualTime()->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();

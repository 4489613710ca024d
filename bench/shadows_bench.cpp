// The shadows lab. BM_ShadowFilter: per light type, filter and PCF kernel; BM_ShadowFrameworkOverhead:
// the lab's frame beside a bare two-pass program (below); BM_ShadowTruth: the ray-traced truth by
// Embree and by the GPU tracer.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "bench_common.h"
#include "labs/shadows/shadow_options.h"
#include "labs/shadows/shadows_lab.h"

using namespace shadelab;

namespace {

// BM_ShadowFilter/<light>/<filter>/<pcf N>: GPU ms of a shadows-lab frame (depth pass + lighting) at
// 1280x720, per light type and filter, on the default shadow scene.
void BM_ShadowFilter(benchmark::State& state) {
  LabHost host(ShaderSearchPath({builtinShaderDir()}));
  host.selectLab("shadows");
  const std::string light(kLightTypes[state.range(0)].name);
  host.set("shadows.light_type=" + light);
  host.set("shadows.light_distance=1.2");
  const std::string filter = filterName(ShadowFilter(state.range(1)));
  host.set("shadows.filter=" + filter);
  host.set("shadows.pcf_size=" + std::to_string(state.range(2)));
  timeFrames(state, host, {1280, 720});
  state.SetLabel(
      light + " " + filter +
      (state.range(1) == 2 ? " " + std::to_string(state.range(2)) + "x" + std::to_string(state.range(2)) : ""));
}
BENCHMARK(BM_ShadowFilter)
    ->ArgsProduct({{0, 2}, {0, 1, 3, 4}, {3}})
    ->ArgsProduct({{0, 2}, {2}, {3, 5, 9, 15}})
    ->ArgsProduct({{0}, {5, 6, 7}, {3}})  // filtered maps: depth + moments, blur, mips, lighting
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(10);

// BM_ShadowFrameworkOverhead: what the lab's machinery costs per frame. The lab's frame (host,
// pass timers, uniform lookups by name, light set-up, dummy bindings) beside a bare two-pass
// program of the same scene and settings: its own VAOs, depth texture and framebuffers (an
// RGBA16F colour target, as the host's), the
// lab's own compiled programs with the uniforms the lab's frame left in them, then per frame a
// depth pass and a 3x3 PCF lighting pass of raw draw calls, no timer queries. Both end in
// glFinish and are timed by the wall clock, interleaved frame by frame so the machine's drift
// falls on both; counters: median ms of each and their ratio.
void BM_ShadowFrameworkOverhead(benchmark::State& state) {
  const glm::ivec2 size(1280, 720);
  LabHost host(ShaderSearchPath({builtinShaderDir()}));
  host.selectLab("shadows");
  host.set("shadows.filter=pcf");
  host.set("shadows.pcf_size=3");
  for (int i = 0; i < 3; ++i) host.renderFrame(size);
  GLuint lit = 0, depth = 0;
  for (auto& p : host.lab().activePrograms()) {
    GLint id = 0;
    p->use();
    glGetIntegerv(GL_CURRENT_PROGRAM, &id);
    if (p->spec().name.rfind("shadows/lit", 0) == 0) lit = GLuint(id);
    if (p->spec().name == "shadows/depth") depth = GLuint(id);
  }
  if (!lit || !depth) return state.SkipWithError("the lab's programs were not found");

  // The bare program's own objects.
  const Scene& scene = host.scene();
  struct Mesh {
    GLuint vao, vbo[2], ibo;
    GLsizei count;
  };
  std::vector<Mesh> meshes;
  for (const MeshData& m : scene.meshes) {
    Mesh g{};
    glGenVertexArrays(1, &g.vao);
    glGenBuffers(2, g.vbo);
    glGenBuffers(1, &g.ibo);
    glBindVertexArray(g.vao);
    const std::vector<glm::vec3>* attrs[2] = {&m.positions, &m.normals};
    for (GLuint a = 0; a < 2; ++a) {
      glBindBuffer(GL_ARRAY_BUFFER, g.vbo[a]);
      glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(attrs[a]->size() * sizeof(glm::vec3)), attrs[a]->data(), GL_STATIC_DRAW);
      glEnableVertexAttribArray(a);
      glVertexAttribPointer(a, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
    }
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, g.ibo);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(m.indices.size() * 4), m.indices.data(), GL_STATIC_DRAW);
    g.count = GLsizei(m.indices.size());
    meshes.push_back(g);
  }
  glBindVertexArray(0);
  const int mapSize = 2048;  // the lab's default map
  GLuint shadowTex = 0, shadowFbo = 0, colorTex = 0, depthRb = 0, targetFbo = 0;
  glGenTextures(1, &shadowTex);
  glBindTexture(GL_TEXTURE_2D_ARRAY, shadowTex);
  glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_DEPTH_COMPONENT24, mapSize, mapSize, 1, 0, GL_DEPTH_COMPONENT, GL_FLOAT,
               nullptr);
  depthMapSampling(GL_TEXTURE_2D_ARRAY);
  glGenFramebuffers(1, &shadowFbo);
  glBindFramebuffer(GL_FRAMEBUFFER, shadowFbo);
  glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, shadowTex, 0, 0);
  glDrawBuffer(GL_NONE);
  glGenTextures(1, &colorTex);
  glBindTexture(GL_TEXTURE_2D, colorTex);
  // The lab's frame renders into a half-float target (so metrics read linear values): the same here.
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16F, size.x, size.y, 0, GL_RGBA, GL_FLOAT, nullptr);
  glGenRenderbuffers(1, &depthRb);
  glBindRenderbuffer(GL_RENDERBUFFER, depthRb);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, size.x, size.y);
  glGenFramebuffers(1, &targetFbo);
  glBindFramebuffer(GL_FRAMEBUFFER, targetFbo);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colorTex, 0);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, depthRb);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  const GLint depthModel = glGetUniformLocation(depth, "u_model");
  const GLint litModel = glGetUniformLocation(lit, "u_model"), litNormal = glGetUniformLocation(lit, "u_normalMatrix"),
              litColor = glGetUniformLocation(lit, "u_baseColor");

  const std::vector<size_t> litOrder = scene.nearestFirst(host.camera().eye());
  auto bareFrame = [&] {
    glBindFramebuffer(GL_FRAMEBUFFER, shadowFbo);
    glViewport(0, 0, mapSize, mapSize);
    glEnable(GL_DEPTH_TEST);
    glClear(GL_DEPTH_BUFFER_BIT);
    glUseProgram(depth);
    for (const Instance& inst : scene.instances) {
      glUniformMatrix4fv(depthModel, 1, GL_FALSE, glm::value_ptr(inst.model));
      glBindVertexArray(meshes[size_t(inst.mesh)].vao);
      glDrawElements(GL_TRIANGLES, meshes[size_t(inst.mesh)].count, GL_UNSIGNED_INT, nullptr);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, targetFbo);
    glViewport(0, 0, size.x, size.y);
    glClearColor(0.02f, 0.02f, 0.025f, 0.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glUseProgram(lit);
    glActiveTexture(GL_TEXTURE0);  // the lab's u_keyMap unit
    glBindTexture(GL_TEXTURE_2D_ARRAY, shadowTex);
    glBindSampler(0, 0);
    for (size_t i : litOrder) {  // the lab's order: the nearest instance first
      const Instance& inst = scene.instances[i];
      const MeshData& m = scene.meshes[size_t(inst.mesh)];
      glUniformMatrix4fv(litModel, 1, GL_FALSE, glm::value_ptr(inst.model));
      glUniformMatrix3fv(litNormal, 1, GL_FALSE, glm::value_ptr(glm::mat3(glm::inverseTranspose(inst.model))));
      glUniform4fv(litColor, 1, glm::value_ptr(scene.materials[size_t(m.material)].baseColor));
      glBindVertexArray(meshes[size_t(inst.mesh)].vao);
      glDrawElements(GL_TRIANGLES, meshes[size_t(inst.mesh)].count, GL_UNSIGNED_INT, nullptr);
    }
    glFinish();
  };
  auto wall = [](auto&& f) {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  };
  std::vector<double> labMs, bareMs, labPassCpuMs;
  for (int i = 0; i < 3; ++i) bareFrame();
  for (auto _ : state) {
    for (int i = 0; i < int(state.range(0)); ++i) {
      double passCpu = 0;
      labMs.push_back(wall([&] {
        for (auto& pass : host.renderFrame(size)) passCpu += pass.cpuMs;
        glFinish();
      }));
      labPassCpuMs.push_back(passCpu);
      bareMs.push_back(wall(bareFrame));
    }
    state.SetIterationTime(1e-3);  // the counters carry the result
  }
  auto median = [](std::vector<double> v) {
    std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
    return v[v.size() / 2];
  };
  state.counters["lab_ms"] = median(labMs);
  state.counters["bare_ms"] = median(bareMs);
  state.counters["ratio"] = median(labMs) / median(bareMs);
  state.counters["lab_pass_cpu_ms"] = median(labPassCpuMs);  // CPU time inside the lab's passes
  state.SetLabel("shadow-test 1280x720, directional 2048^2, 3x3 PCF, median of " + std::to_string(labMs.size()) +
                 " frames each, interleaved");
  for (auto& g : meshes) {
    glDeleteVertexArrays(1, &g.vao);
    glDeleteBuffers(2, g.vbo);
    glDeleteBuffers(1, &g.ibo);
  }
  glDeleteFramebuffers(1, &shadowFbo);
  glDeleteFramebuffers(1, &targetFbo);
  glDeleteTextures(1, &shadowTex);
  glDeleteTextures(1, &colorTex);
  glDeleteRenderbuffers(1, &depthRb);
}
BENCHMARK(BM_ShadowFrameworkOverhead)->Arg(300)->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(1);

// BM_ShadowTruth/<tracer>/<area>: wall ms of the ray-traced truth of one 1280x720 frame of the
// default scene, g-buffer included: tracer 0 Embree (CPU threads), 1 the GPU tracer (a fragment
// shader over the BVH); area 0 the hard truth alone (light radius 0: one ray a pixel), 1 the area
// truth too (64 stratified rays a pixel). Run side by side: their ratio is the figure to quote.
void BM_ShadowTruth(benchmark::State& state) {
  LabHost host(ShaderSearchPath({builtinShaderDir()}));
  host.selectLab("shadows");
  const bool gpu = state.range(0) == 1, area = state.range(1) == 1;
  host.set(std::string("shadows.truth_tracer=") + (gpu ? "gpu" : "embree"));
  if (!area) host.set("shadows.light_radius=0");
  host.renderFrame({1280, 720});
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    const ImageF truth = host.renderReference({1280, 720});
    benchmark::DoNotOptimize(truth.rgba.data());
    state.SetIterationTime(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  state.SetLabel(std::string(gpu ? "gpu" : "embree") + (area ? ", hard + area (64 samples)" : ", hard only"));
}
BENCHMARK(BM_ShadowTruth)->ArgsProduct({{0, 1}, {0, 1}})->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(3);

// BM_GpuTruthShape/<samples a draw>/<walk width>/<leaf size>/<cone>: the GPU tracer's 64-sample
// area truth of the default 1280x720 frame (as BM_ShadowTruth/1/1), cut into draws, walks and
// leaves of each size, with or without the cone test (GpuTraceShape). Wall ms of the whole truth (g-buffer, trace,
// read-back); counter trace_ms: the trace's own steps.
void BM_GpuTruthShape(benchmark::State& state) {
  LabHost host(ShaderSearchPath({builtinShaderDir()}));
  host.selectLab("shadows");
  host.set("shadows.truth_tracer=gpu");
  auto& lab = dynamic_cast<ShadowsLab&>(host.lab());
  const GpuTraceShape shape{int(state.range(0)), int(state.range(1)), int(state.range(2)), state.range(3) != 0};
  lab.setTracerShape(shape);
  host.renderFrame({1280, 720});
  host.renderReference({1280, 720});  // compiles the program, builds the BVH
  double traceMs = 0.0;
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    const ImageF truth = host.renderReference({1280, 720});
    benchmark::DoNotOptimize(truth.rgba.data());
    state.SetIterationTime(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    traceMs += lab.gpuTracer() ? lab.gpuTracer()->traceMs() : 0.0;
  }
  state.counters["trace_ms"] = traceMs / double(std::max<benchmark::IterationCount>(state.iterations(), 1));
  state.SetLabel(std::to_string(shape.samplesPerDraw) + " samples a draw, walks of " + std::to_string(shape.walkWidth) +
                 ", leaves of " + std::to_string(shape.leafSize) + (shape.coneCull ? ", cone" : ""));
}
BENCHMARK(BM_GpuTruthShape)
    ->ArgsProduct({{16}, {4, 8, 16}, {1, 2, 4}, {0, 1}})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);

}  // namespace

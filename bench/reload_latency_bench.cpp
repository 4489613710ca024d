// Benchmarks that need a GL context (OSMesa or EGL). Run: build/bench/shadelab_bench
//
// BM_ReloadLatency: a student saves shade.frag; how long until the first frame drawn with the new
// program? Measured from just before the write to the end of the first frame whose program build
// count went up, through the real path: inotify -> debounce -> preprocess -> compile -> link -> draw.
// BM_CompileProgram: the compile + link part of that, for one program.
// BM_Frame/<mode>: one 1280x720 frame of the shading lab's default scene, per shading mode.
// BM_ShadowFilter: the shadows lab per light type, filter and PCF kernel (below).
// BM_SurfaceTechnique: the surface lab per technique and its knob (below).
// BM_DenoiseFrame: the denoising lab's frame, idle and while a job runs (below).
// BM_FilteringFilter: the filtering lab per filter on its grazing plane; BM_FilteringReference: its
// supersampled truth for one frame (below).
// BM_ShadowFrameworkOverhead: the shadows lab's frame beside a bare two-pass program (below).
#include <benchmark/benchmark.h>

#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include <algorithm>

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "context/gl_context.h"
#include "host/lab_host.h"

namespace fs = std::filesystem;
using namespace shadelab;

namespace {

std::unique_ptr<GlContext> g_context;

std::string readFile(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

void BM_ReloadLatency(benchmark::State& state) {
  const fs::path builtin = builtinShaderDir();
  const fs::path student = fs::temp_directory_path() / ("shadelab_bench_" + std::to_string(::getpid()));
  fs::create_directories(student / "shading");
  const fs::path frag = student / "shading" / "shade.frag";
  const std::string original = readFile(builtin / "shading" / "shade.frag");
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

// Each iteration is one frame, timed by the sum of its passes' GPU time (after two warm-up frames).
void timeFrames(benchmark::State& state, LabHost& host, glm::ivec2 size) {
  for (int i = 0; i < 2; ++i) host.renderFrame(size);
  for (auto _ : state) {
    double gpu = 0;
    for (auto& pass : host.renderFrame(size)) gpu += pass.gpuMs;
    state.SetIterationTime(gpu / 1000.0);
  }
}

// One configuration of `lab` (its `key=value` settings, with `extra` first) timed as above, and
// labelled with the settings.
void timeConfiguration(benchmark::State& state, const char* lab, const std::vector<std::string>& config,
                       const std::vector<std::string>& extra = {}) {
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

// The compile + link share of the reload: one program of the shading lab, rebuilt from disk.
void BM_CompileProgram(benchmark::State& state) {
  LabHost host(ShaderSearchPath({builtinShaderDir()}));
  host.renderFrame({64, 64});
  Program& p = *host.lab().activePrograms().front();
  for (auto _ : state) host.shaders().rebuild(p, /*force=*/true);
}
BENCHMARK(BM_CompileProgram)->Unit(benchmark::kMillisecond)->Iterations(10);

void BM_Frame(benchmark::State& state) {
  static const char* modes[] = {"flat", "gouraud", "phong"};
  LabHost host(ShaderSearchPath({builtinShaderDir()}));
  host.set(std::string("shading.mode=") + modes[state.range(0)]);
  timeFrames(state, host, {1280, 720});
  state.SetLabel(modes[state.range(0)]);
}
BENCHMARK(BM_Frame)->DenseRange(0, 2)->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(20);

// BM_ShadowFilter/<light>/<filter>/<pcf N>: GPU ms of a shadows-lab frame (depth pass + lighting) at
// 1280x720, per light type and filter, on the default shadow scene.
void BM_ShadowFilter(benchmark::State& state) {
  static const char* lights[] = {"directional", "spot", "point"};
  static const char* filters[] = {"hard", "hardware-pcf", "pcf", "poisson", "pcss", "vsm", "esm", "evsm"};
  LabHost host(ShaderSearchPath({builtinShaderDir()}));
  host.selectLab("shadows");
  host.set(std::string("shadows.light_type=") + lights[state.range(0)]);
  host.set("shadows.light_distance=1.2");
  host.set(std::string("shadows.filter=") + filters[state.range(1)]);
  host.set("shadows.pcf_size=" + std::to_string(state.range(2)));
  timeFrames(state, host, {1280, 720});
  state.SetLabel(std::string(lights[state.range(0)]) + " " + filters[state.range(1)] +
                 (state.range(1) == 2 ? " " + std::to_string(state.range(2)) + "x" + std::to_string(state.range(2)) : ""));
}
BENCHMARK(BM_ShadowFilter)
    ->ArgsProduct({{0, 2}, {0, 1, 3, 4}, {3}})
    ->ArgsProduct({{0, 2}, {2}, {3, 5, 9, 15}})
    ->ArgsProduct({{0}, {5, 6, 7}, {3}})  // filtered maps: depth + moments, blur, mips, lighting
    ->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(10);

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
    ->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(10);

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
  host.jobs().setLowPriority(true);  // as in the window
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
    ->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(10);

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
  struct Mesh { GLuint vao, vbo[2], ibo; GLsizei count; };
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
  glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_DEPTH_COMPONENT24, mapSize, mapSize, 1, 0, GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
  const float white[4] = {1, 1, 1, 1};
  glTexParameterfv(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_BORDER_COLOR, white);
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
    for (const Instance& inst : scene.instances) {
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

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  const char* backend = std::getenv("SHADELAB_BACKEND");
  std::string err;
  g_context = createHeadlessContext(backend ? backend : "osmesa", err);
  if (!g_context) {
    std::fprintf(stderr, "shadelab_bench: %s\n", err.c_str());
    return 1;
  }
  std::fprintf(stderr, "renderer: %s\n", g_context->describe().c_str());
  benchmark::RunSpecifiedBenchmarks();
  g_context.reset();
  return 0;
}

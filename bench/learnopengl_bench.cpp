// BM_LearnOpenGLFrame: the shadows lab on the `learnopengl` scene beside the method of LearnOpenGL's
// shadow-mapping chapter written plainly here, so the lab's frame is held to the chapter's without
// the chapter's code. The plain program is what the chapter's final listing does, step for step:
//   depth pass: a 1024^2 depth texture (24 bits, nearest, clamped to a border of 1), an
//     orthographic light box of +-10 from near 1 to far 7.5, the light at (-2, 4, -1) looking at
//     the origin, every object drawn, no culling;
//   lighting pass: into an 8-bit RGBA target with a depth buffer; per fragment a mipmapped
//     diffuse texture (the floor's repeats 25 times), ambient + Lambert + Blinn-Phong (exponent
//     64) from the light's position, and a 3x3 PCF of plain texture() reads compared in the
//     shader with the slope bias max(0.05 (1 - N.L), 0.005); receivers past the far plane lit.
// The lab runs at the chapter's size (800x600) either as the scene opens, with the scene's own
// defaults (four 512^2 cascades and the lab's 3x3 PCF: the chapter's memory, split), or at the
// chapter's settings (one 1024^2 map fitted to the view, 3x3 PCF). Both frames end in glFinish and
// are timed by the wall clock, interleaved frame by frame so the machine's drift falls on both;
// counters: median ms of each and their ratio, the lab's passes' GPU time (its depth passes and
// the rest), the plain program drawing into the lab's half-float target, and the lab's
// misclassified pixels against Embree's ray-traced visibility (the chapter's own box misclassifies
// 0.085 % of this view: tutorials/shadows.md, section 10).
// Args: the plain program's floor: 0 = it samples its diffuse texture, as the chapter does; 1 = it
// reads a constant colour, as the lab's scene does (the lab's floor has no image); the lab's
// settings: 0 = the scene's own defaults, 1 = one map fitted to the view, 2 = one map fitted to the
// view with the receiver plane off: the chapter's settings in full (its taps compare against the
// centre depth).
//
// BM_DefaultFit/<scene>: how sharp each scene's default shadows are beside the best the map's
// fits do there: the percentage of pixels misclassified (lit against shadowed) against Embree's
// ray-traced visibility, at 800x600 with hard shadows, for the scene's defaults (its suggested
// settings included) and for fit=scene, view and cascades; `default_over_best` is 1 when the
// default is the best fit.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "app/gl/handle.h"
#include "app/host/measurer.h"
#include "app/scene/procedural.h"
#include "bench_common.h"

using namespace shadelab;

namespace {

const char* kDepthVert = R"(#version 330 core
layout(location = 0) in vec3 a_position;
uniform mat4 u_lightSpace;
uniform mat4 u_model;
void main() { gl_Position = u_lightSpace * u_model * vec4(a_position, 1.0); }
)";
const char* kDepthFrag = R"(#version 330 core
void main() {}
)";
const char* kLitVert = R"(#version 330 core
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;
uniform mat4 u_viewProj;
uniform mat4 u_model;
uniform mat4 u_lightSpace;
out vec3 v_world;
out vec3 v_normal;
out vec2 v_uv;
out vec4 v_light;
void main() {
  v_world = vec3(u_model * vec4(a_position, 1.0));
  v_normal = transpose(inverse(mat3(u_model))) * a_normal;
  v_uv = a_uv;
  v_light = u_lightSpace * vec4(v_world, 1.0);
  gl_Position = u_viewProj * vec4(v_world, 1.0);
}
)";
const char* kLitFrag = R"(#version 330 core
in vec3 v_world;
in vec3 v_normal;
in vec2 v_uv;
in vec4 v_light;
uniform sampler2D u_diffuse;
uniform sampler2D u_shadowMap;
uniform vec3 u_lightPos;
uniform vec3 u_eye;
uniform vec3 u_color;
uniform bool u_textured;
out vec4 o_color;

float shadowed(vec4 lightClip, vec3 N, vec3 L) {
  vec3 p = lightClip.xyz / lightClip.w * 0.5 + 0.5;
  if (p.z > 1.0) return 0.0;
  float bias = max(0.05 * (1.0 - dot(N, L)), 0.005);
  vec2 texel = 1.0 / vec2(textureSize(u_shadowMap, 0));
  float sum = 0.0;
  for (int x = -1; x <= 1; ++x)
    for (int y = -1; y <= 1; ++y)
      sum += p.z - bias > texture(u_shadowMap, p.xy + vec2(x, y) * texel).r ? 1.0 : 0.0;
  return sum / 9.0;
}

void main() {
  vec3 albedo = u_textured ? texture(u_diffuse, v_uv).rgb : u_color;
  vec3 N = normalize(v_normal);
  vec3 light = vec3(0.3);
  vec3 L = normalize(u_lightPos - v_world);
  vec3 V = normalize(u_eye - v_world);
  vec3 H = normalize(L + V);
  vec3 diffuse = max(dot(L, N), 0.0) * light;
  vec3 specular = pow(max(dot(N, H), 0.0), 64.0) * light;
  float shadow = shadowed(v_light, N, L);
  o_color = vec4((0.3 * light + (1.0 - shadow) * (diffuse + specular)) * albedo, 1.0);
}
)";

GLuint compile(const char* vert, const char* frag) {
  const GLuint program = glCreateProgram();
  for (auto [type, source] : {std::pair{GL_VERTEX_SHADER, vert}, std::pair{GL_FRAGMENT_SHADER, frag}}) {
    const GLuint shader = glCreateShader(type);
    glShaderSource(shader, 1, &source, nullptr);
    glCompileShader(shader);
    GLint ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
      char log[2048];
      glGetShaderInfoLog(shader, sizeof log, nullptr, log);
      std::fprintf(stderr, "learnopengl_bench: %s\n", log);
    }
    glAttachShader(program, shader);
    glDeleteShader(shader);
  }
  glLinkProgram(program);
  return program;
}

struct PlainMesh {
  gl::VertexArray vao;
  gl::Buffer vbo[3], ibo;
  GLsizei count = 0;
  glm::mat4 model{1.0f};
  bool floor = false;
};

PlainMesh upload(const MeshData& m, const glm::mat4& model, bool floor) {
  PlainMesh g;
  g.vao = gl::VertexArray::make();
  g.ibo = gl::Buffer::make();
  g.model = model;
  g.floor = floor;
  glBindVertexArray(g.vao.get());
  auto attribute = [&](GLuint index, const void* data, size_t bytes, GLint components) {
    g.vbo[index] = gl::Buffer::make();
    glBindBuffer(GL_ARRAY_BUFFER, g.vbo[index].get());
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(bytes), data, GL_STATIC_DRAW);
    glEnableVertexAttribArray(index);
    glVertexAttribPointer(index, components, GL_FLOAT, GL_FALSE, 0, nullptr);
  };
  attribute(0, m.positions.data(), m.positions.size() * sizeof(glm::vec3), 3);
  attribute(1, m.normals.data(), m.normals.size() * sizeof(glm::vec3), 3);
  attribute(2, m.uvs.data(), m.uvs.size() * sizeof(glm::vec2), 2);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, g.ibo.get());
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(m.indices.size() * 4), m.indices.data(), GL_STATIC_DRAW);
  g.count = GLsizei(m.indices.size());
  glBindVertexArray(0);
  return g;
}

double median(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
  return v[v.size() / 2];
}

void BM_LearnOpenGLFrame(benchmark::State& state) {
  const glm::ivec2 size(800, 600);
  const int mapSize = 1024;
  const bool textured = state.range(0) == 0, sceneDefaults = state.range(1) == 0, plane = state.range(1) != 2;
  LabHost host(ShaderSearchPath({builtinShaderDir()}), "shadows", "learnopengl");
  if (!sceneDefaults) {
    host.set("shadows.fit=view");
    host.set("shadows.map_size=1024");
    host.set("shadows.filter=pcf");
    host.set("shadows.pcf_size=3");
  }
  if (!plane) host.set("shadows.receiver_plane=off");
  std::string labSettings;
  for (auto& [k, v] : host.currentSettings())
    if (k == "fit" || k == "map_size" || k == "cascade_count" || k == "filter" || k == "pcf_size")
      labSettings += (labSettings.empty() ? "" : " ") + k + "=" + v;
  for (int i = 0; i < 3; ++i) host.renderFrame(size);

  // The chapter's scene, built as the lab's recipe builds it, with UVs for the floor's image.
  std::vector<PlainMesh> meshes;
  const glm::mat4 I(1.0f);
  meshes.push_back(upload(makePlane(50.0f, 1, 25.0f), glm::translate(I, glm::vec3(0.0f, -0.5f, 0.0f)), true));
  meshes.push_back(upload(makeBox(glm::vec3(0.5f)), glm::translate(I, glm::vec3(0.0f, 1.5f, 0.0f)), false));
  meshes.push_back(upload(makeBox(glm::vec3(0.5f)), glm::translate(I, glm::vec3(2.0f, 0.0f, 1.0f)), false));
  meshes.push_back(upload(makeBox(glm::vec3(0.25f)),
                          glm::rotate(glm::translate(I, glm::vec3(-1.0f, 0.0f, 2.0f)), glm::radians(60.0f),
                                      glm::normalize(glm::vec3(1.0f, 0.0f, 1.0f))),
                          false));

  // A 512^2 mipmapped RGBA8 image in place of the chapter's wood.
  std::vector<unsigned char> pixels(512 * 512 * 4);
  for (int y = 0; y < 512; ++y)
    for (int x = 0; x < 512; ++x) {
      const int grain = 150 + ((x * 7 + (y / 32) * 37) % 60);
      unsigned char* p = &pixels[size_t(y * 512 + x) * 4];
      p[0] = (unsigned char)grain, p[1] = (unsigned char)(grain * 3 / 4), p[2] = (unsigned char)(grain / 2), p[3] = 255;
    }
  gl::TextureName diffuse = gl::TextureName::make(), shadowMap = gl::TextureName::make(),
                  colour = gl::TextureName::make();
  glBindTexture(GL_TEXTURE_2D, diffuse.get());
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 512, 512, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  glGenerateMipmap(GL_TEXTURE_2D);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  glBindTexture(GL_TEXTURE_2D, shadowMap.get());
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, mapSize, mapSize, 0, GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
  depthMapSampling(GL_TEXTURE_2D);
  gl::FramebufferName shadowFbo = gl::FramebufferName::make(), targetFbo = gl::FramebufferName::make();
  glBindFramebuffer(GL_FRAMEBUFFER, shadowFbo.get());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, shadowMap.get(), 0);
  glDrawBuffer(GL_NONE);
  glReadBuffer(GL_NONE);
  glBindTexture(GL_TEXTURE_2D, colour.get());
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, size.x, size.y, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  // The same frame into a half-float target, as the lab's (so metrics read linear values): what
  // that target costs.
  gl::TextureName halfColour = gl::TextureName::make();
  glBindTexture(GL_TEXTURE_2D, halfColour.get());
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16F, size.x, size.y, 0, GL_RGBA, GL_FLOAT, nullptr);
  gl::Renderbuffer depthRb = gl::Renderbuffer::make();
  glBindRenderbuffer(GL_RENDERBUFFER, depthRb.get());
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, size.x, size.y);
  gl::FramebufferName halfFbo = gl::FramebufferName::make();
  for (auto [fbo, tex] : {std::pair{targetFbo.get(), colour.get()}, std::pair{halfFbo.get(), halfColour.get()}}) {
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, depthRb.get());
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);

  const GLuint depthProgram = compile(kDepthVert, kDepthFrag), litProgram = compile(kLitVert, kLitFrag);
  const glm::vec3 lightPos(-2.0f, 4.0f, -1.0f),
      eye = glm::vec3(0.0f, 0.0f, 0.5f) +
            7.0f * glm::vec3(0.0f, std::sin(glm::radians(25.0f)), std::cos(glm::radians(25.0f)));
  const glm::mat4 lightSpace = glm::ortho(-10.0f, 10.0f, -10.0f, 10.0f, 1.0f, 7.5f) *
                               glm::lookAt(lightPos, glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
  const glm::mat4 viewProj = glm::perspective(glm::radians(45.0f), float(size.x) / float(size.y), 0.1f, 100.0f) *
                             glm::lookAt(eye, glm::vec3(0.0f, 0.0f, 0.5f), glm::vec3(0.0f, 1.0f, 0.0f));
  glUseProgram(depthProgram);
  glUniformMatrix4fv(glGetUniformLocation(depthProgram, "u_lightSpace"), 1, GL_FALSE, glm::value_ptr(lightSpace));
  glUseProgram(litProgram);
  glUniformMatrix4fv(glGetUniformLocation(litProgram, "u_lightSpace"), 1, GL_FALSE, glm::value_ptr(lightSpace));
  glUniformMatrix4fv(glGetUniformLocation(litProgram, "u_viewProj"), 1, GL_FALSE, glm::value_ptr(viewProj));
  glUniform3fv(glGetUniformLocation(litProgram, "u_lightPos"), 1, glm::value_ptr(lightPos));
  glUniform3fv(glGetUniformLocation(litProgram, "u_eye"), 1, glm::value_ptr(eye));
  glUniform1i(glGetUniformLocation(litProgram, "u_diffuse"), 0);
  glUniform1i(glGetUniformLocation(litProgram, "u_shadowMap"), 1);
  glUniform1i(glGetUniformLocation(litProgram, "u_textured"), textured ? 1 : 0);
  const GLint depthModel = glGetUniformLocation(depthProgram, "u_model"),
              litModel = glGetUniformLocation(litProgram, "u_model"),
              litColor = glGetUniformLocation(litProgram, "u_color");

  auto plainFrame = [&](GLuint target) {
    glBindFramebuffer(GL_FRAMEBUFFER, shadowFbo.get());
    glViewport(0, 0, mapSize, mapSize);
    glEnable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glClear(GL_DEPTH_BUFFER_BIT);
    glUseProgram(depthProgram);
    for (const PlainMesh& m : meshes) {
      glUniformMatrix4fv(depthModel, 1, GL_FALSE, glm::value_ptr(m.model));
      glBindVertexArray(m.vao.get());
      glDrawElements(GL_TRIANGLES, m.count, GL_UNSIGNED_INT, nullptr);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, target);
    glViewport(0, 0, size.x, size.y);
    glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glUseProgram(litProgram);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, diffuse.get());
    glBindSampler(0, 0);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, shadowMap.get());
    glBindSampler(1, 0);
    for (const PlainMesh& m : meshes) {  // the floor first, then the cubes, as the chapter draws them
      glUniformMatrix4fv(litModel, 1, GL_FALSE, glm::value_ptr(m.model));
      glUniform3f(litColor, m.floor ? 0.72f : 0.85f, m.floor ? 0.7f : 0.55f, m.floor ? 0.66f : 0.35f);
      glBindVertexArray(m.vao.get());
      glDrawElements(GL_TRIANGLES, m.count, GL_UNSIGNED_INT, nullptr);
    }
    glActiveTexture(GL_TEXTURE0);
    glFinish();
  };
  auto wall = [](auto&& f) {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  };
  std::vector<double> labMs, plainMs, plainHalfMs, labDepthMs, labLitMs;
  for (int i = 0; i < 3; ++i) plainFrame(targetFbo.get());
  for (auto _ : state) {
    for (int i = 0; i < 100; ++i) {
      double depth = 0, lit = 0;
      labMs.push_back(wall([&] {
        for (auto& pass : host.renderFrame(size)) (pass.name.rfind("shadow map", 0) == 0 ? depth : lit) += pass.gpuMs;
        glFinish();
      }));
      labDepthMs.push_back(depth);
      labLitMs.push_back(lit);
      plainMs.push_back(wall([&] { plainFrame(targetFbo.get()); }));
      plainHalfMs.push_back(wall([&] { plainFrame(halfFbo.get()); }));
    }
    state.SetIterationTime(1e-3);  // the counters carry the result
  }
  glDeleteProgram(depthProgram);
  glDeleteProgram(litProgram);
  Measurer measurer(host);  // after the timing: the truth is traced on the CPU
  if (const auto m = measurer.measureNow(size, 0.0f, {}))
    state.counters["misclassified_pct"] = m->value("misclassified_pct");
  state.counters["lab_ms"] = median(labMs);
  state.counters["chapter_ms"] = median(plainMs);
  state.counters["ratio"] = median(labMs) / median(plainMs);
  state.counters["chapter_rgba16f_ms"] = median(plainHalfMs);
  state.counters["lab_depth_gpu_ms"] = median(labDepthMs);
  state.counters["lab_lighting_gpu_ms"] = median(labLitMs);
  state.SetLabel(std::string("learnopengl 800x600; the chapter: one 1024^2 map, 3x3 PCF; the lab: ") +
                 (sceneDefaults ? "the scene's defaults (" : "the chapter's settings (") + labSettings + ")" +
                 (plane ? "" : ", no receiver plane") + "; chapter's floor " +
                 (textured ? "textured" : "a constant colour") + "; median of " + std::to_string(labMs.size()) +
                 " frames each, interleaved");
}
BENCHMARK(BM_LearnOpenGLFrame)
    ->Args({0, 0})
    ->Args({1, 0})
    ->Args({0, 1})
    ->Args({1, 1})
    ->Args({0, 2})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

const char* kFitScenes[] = {"shadow-test", "learnopengl", "spot-on-plane", "teapot-on-plane"};

void BM_DefaultFit(benchmark::State& state) {
  const std::string scene = kFitScenes[state.range(0)];
  const glm::ivec2 size(800, 600);
  LabHost host(ShaderSearchPath({builtinShaderDir()}), "shadows", scene);
  if (host.sceneId() != scene) return state.SkipWithError(("scene " + scene + " is not here").c_str());
  Measurer measurer(host);
  auto misclassified = [&] {
    host.set("shadows.filter=hard");  // the map's resolution is all that differs
    const auto m = measurer.measureNow(size, 0.0f, {});
    return m ? m->value("misclassified_pct") : std::nan("");
  };
  std::string defaultFit;
  for (auto& [k, v] : host.currentSettings())
    if (k == "fit") defaultFit = v;
  for (auto _ : state) {
    const double atDefault = misclassified();
    double best = atDefault;
    for (const char* fit : {"scene", "view", "cascades"}) {
      host.resetParams();
      host.set(std::string("shadows.fit=") + fit);
      const double v = misclassified();
      state.counters[std::string(fit) + "_pct"] = v;
      best = std::min(best, v);
    }
    state.counters["default_pct"] = atDefault;
    state.counters["default_over_best"] = atDefault / best;
    state.SetIterationTime(1e-3);  // the counters carry the result
  }
  state.SetLabel(scene + ", default fit " + defaultFit + ", hard shadows, 800x600, vs Embree");
}
BENCHMARK(BM_DefaultFit)->DenseRange(0, 3)->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace

#include "labs/shadows/gpu_tracer.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <numeric>
#include <thread>

#include "app/util/process_memory.h"
#include "labs/shadows/ray_visibility.h"

namespace shadelab {
namespace {

constexpr int kTextureWidthLog2 = 10;  // 1024 texels per row of the BVH textures (within every GL 3.3 and WebGL2 limit)
gl::Texture2D floatTexture(const std::vector<glm::vec4>& texels, int width) {
  const int rows = std::max(1, int((texels.size() + size_t(width) - 1) / size_t(width)));
  std::vector<glm::vec4> padded(size_t(width) * size_t(rows), glm::vec4(0.0f));
  std::copy(texels.begin(), texels.end(), padded.begin());
  gl::SamplerState s;
  s.minFilter = s.magFilter = GL_NEAREST;
  return gl::Texture2D::fromData({width, rows}, GL_RGBA32F, GL_RGBA, GL_FLOAT, padded.data(), s);
}

// The n x n disk samples in an order that spreads every prefix over the disk: k -> 37 k mod n^2
// (37 is prime to every power of two, and to most other n^2 the lab uses).
glm::vec2 diskSampleAt(int pass, int perAxis) {
  const int cells = perAxis * perAxis;
  int k = (pass * 37) % cells;
  if (std::gcd(37, cells) != 1) k = pass % cells;
  return stratifiedDiskSample(k / perAxis, k % perAxis, perAxis);
}

}  // namespace

GpuShadowTracer::GpuShadowTracer(Shape shape) : shape_(shape) {
  shape_.samplesPerDraw = std::clamp(shape_.samplesPerDraw, 1, kMaxSamplesPerDraw);
  shape_.walkWidth = std::clamp(shape_.walkWidth, 1, kMaxSamplesPerDraw);  // a draw traces 16 rays at most
  shape_.leafSize = std::clamp(shape_.leafSize, 1, 64);
}

ProgramSpec GpuShadowTracer::resolveSpec() {
  ProgramSpec spec;
  spec.name = "shadows/trace_resolve";
  spec.stages = {{GL_VERTEX_SHADER, "common/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "shadows/trace_resolve.frag"}};
  return spec;
}

ProgramSpec GpuShadowTracer::programSpec(bool oneRay, const GpuTraceShape& shape) {
  ProgramSpec spec;
  spec.name = "shadows/trace";
  spec.stages = {{GL_VERTEX_SHADER, "common/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "shadows/trace.frag"}};
  if (oneRay) spec.defines.emplace_back("ONE_RAY", "1");
  spec.defines.emplace_back("WALK_WIDTH", std::to_string(oneRay ? 1 : shape.walkWidth));
  if (shape.coneCull) spec.defines.emplace_back("CONE_CULL", "1");
  return spec;
}

std::vector<BvhTriangle> sceneTriangles(const Scene& scene) {
  std::vector<BvhTriangle> tris;
  for (auto& inst : scene.instances) {
    const MeshData& m = scene.meshes[size_t(inst.mesh)];
    auto world = [&](uint32_t i) { return glm::vec3(inst.model * glm::vec4(m.positions[i], 1.0f)); };
    for (size_t t = 0; t + 2 < m.indices.size(); t += 3)
      tris.push_back({world(m.indices[t]), world(m.indices[t + 1]), world(m.indices[t + 2])});
  }
  return tris;
}

void GpuShadowTracer::prepare(const Scene& scene) {
  if (bvh_ && revision_ == scene.revision) return;
  bvh_ = std::make_shared<const Bvh>(sceneTriangles(scene), shape_.leafSize);
  const std::vector<glm::vec4> nodes = bvh_->nodeTexels();
  nodeCount_ = int(nodes.size() / 2);
  nodes_ = floatTexture(nodes, 1 << kTextureWidthLog2);
  triangles_ = floatTexture(bvh_->triangleTexels(), 1 << kTextureWidthLog2);
  revision_ = scene.revision;
}

namespace {

// `target` as a render target of `size` and `format`, kept where it already is one.
const gl::RenderTarget& targetOf(std::optional<gl::RenderTarget>& target, glm::ivec2 size, GLenum format) {
  if (!target || target->size() != size) target.emplace(gl::RenderTarget::create(size, format));
  return *target;
}

}  // namespace

const gl::RenderTarget& GpuShadowTracer::positions(glm::ivec2 size) { return targetOf(positions_, size, GL_RGBA32F); }

const gl::RenderTarget& GpuShadowTracer::normals(glm::ivec2 size) { return targetOf(normals_, size, GL_RGBA32F); }

void GpuShadowTracer::begin(const LightFrame& light, int samplesPerAxis, float epsilon) {
  light_ = light;
  perAxis_ = light.radiusWorld > 0.0f ? std::clamp(samplesPerAxis, 1, 15) : 1;
  samples_ = perAxis_ * perAxis_;
  pass_ = 0;
  bandStart_ = 0;
  epsilon_ = epsilon;
  traceMs_ = 0.0;
  if (!positions_ || !normals_) return;  // no g-buffer drawn: nothing to trace
  const glm::ivec2 size = positions_->size();
  targetOf(packed_, size, GL_RGBA8);
  targetOf(sum_, size, GL_RGBA32F).bind();  // (creating a target binds none)
  glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (!vao_) vao_ = gl::VertexArray::make();
}

bool GpuShadowTracer::step(ShaderLibrary& shaders, Programs& programs, double budgetMs) {
  if (!sum_ || !positions_ || pass_ >= samples_ || !bvh_) return false;
  const auto start = std::chrono::steady_clock::now();
  Program& prog = programs.trace.get(shaders, programSpec(light_.radiusWorld <= 0.0f, shape_));
  sum_->bind();
  glViewport(0, 0, sum_->size().x, sum_->size().y);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);  // a float target: the passes add up exactly (sums of 0 and 1)
  prog.use();
  positions_->color().bind(0);
  normals_->color().bind(1);
  nodes_.bind(2);
  triangles_.bind(3);
  prog.set("u_positions", 0);
  prog.set("u_normals", 1);
  prog.set("u_bvhNodes", 2);
  prog.set("u_bvhTriangles", 3);
  prog.set("u_bvhWidthLog2", kTextureWidthLog2);
  prog.set("u_lightType", light_.type == LightType::Directional ? 0 : 1);
  prog.set("u_lightPosition", light_.position);
  prog.set("u_lightDirection", light_.direction);
  prog.set("u_lightRadius", light_.radiusWorld);
  prog.set("u_epsilon", epsilon_);
  prog.set("u_nodeCount", nodeCount_);
  prog.set("u_maxSteps", nodeCount_ + 1);
  glEnable(GL_SCISSOR_TEST);
  glBindVertexArray(vao_.get());
  // Bands until about budgetMs has gone: one band of a pass where a pass is slow (llvmpipe), many
  // whole passes where it is fast (a GPU draws all 64 area samples of a frame within one step).
  const int height = sum_->size().y;
  auto since = [](auto t) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count();
  };
  // The samples of a pass: one in the first, so that a whole first estimate is on screen soon
  // where a pass is slow; up to shape_.samplesPerDraw after it (fixed for all the pass's bands,
  // which trace the same disk points).
  const auto batchAt = [&](int pass) { return pass == 0 ? 1 : std::min(shape_.samplesPerDraw, samples_ - pass); };
  for (;;) {
    const auto bandBegin = std::chrono::steady_clock::now();
    const int batch = batchAt(pass_);
    const int rows = std::clamp(bandRowSamples_ / batch, 1, height - bandStart_);
    for (int k = 0; k < batch; ++k)
      prog.set(("u_disks[" + std::to_string(k) + "]").c_str(), diskSampleAt(pass_ + k, perAxis_));
    prog.set("u_diskCount", batch);
    prog.set("u_pass", pass_);
    glScissor(0, bandStart_, sum_->size().x, rows);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glFinish();
    // The next band's size from this one's time, in rows times samples: about budgetMs a band.
    const double ms = since(bandBegin), perRowSample = std::max(ms, 0.1) / double(rows * batch);
    bandRowSamples_ = std::clamp(int(budgetMs / perRowSample), 4, height * kMaxSamplesPerDraw);
    bandStart_ += rows;
    if (bandStart_ >= height) {
      bandStart_ = 0;
      pass_ += batch;
    }
    if (pass_ >= samples_) break;
    const int nextBatch = batchAt(pass_);
    const int nextRows = std::clamp(bandRowSamples_ / nextBatch, 1, height - bandStart_);
    if (since(start) + perRowSample * double(nextRows * nextBatch) > budgetMs) break;
  }
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_BLEND);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  traceMs_ += since(start);
  return pass_ < samples_;
}

ImageF GpuShadowTracer::result(ShaderLibrary& shaders, Programs& programs, double* standardError) {
  if (!sum_ || !packed_) return {};
  Program& prog = programs.resolve.get(shaders, resolveSpec());
  packed_->bind();
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  prog.use();
  sum_->color().bind(0);
  prog.set("u_sum", 0);
  glBindVertexArray(vao_.get());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);

  // A pixel's values follow from its bytes alone: tables of them, and per band of rows a histogram
  // of the covered pixels' counts (the mean standard error from it) and the rays that gave up.
  const int n = std::max(pass_, 1);
  std::array<float, 256> visible{}, meanOf{};
  for (int b = 0; b < 256; ++b) {
    visible[size_t(b)] = b > 127 ? 1.0f : 0.0f;
    meanOf[size_t(b)] = float(double(std::min(b, n)) / double(n));
  }
  const glm::ivec2 size = sum_->size();
  ImageF out{size, largeBuffer<float>(size_t(size.x) * size_t(size.y) * 4)};
  struct Band {
    std::array<size_t, 256> coveredWith{};
    size_t gaveUp = 0;
  };
  const int bands = std::clamp(int(std::thread::hardware_concurrency()), 1, 8);
  std::vector<Band> tally(static_cast<size_t>(bands));
  packed_->withRgba8([&](const uint8_t* bottomUp) {
    auto decode = [&](int band) {
      Band& t = tally[size_t(band)];
      for (int y = size.y * band / bands; y < size.y * (band + 1) / bands; ++y) {
        const uint8_t* in = bottomUp + size_t(size.y - 1 - y) * size_t(size.x) * 4;
        float* px = &out.rgba[size_t(y) * size_t(size.x) * 4];
        for (int x = 0; x < size.x; ++x, in += 4, px += 4) {
          px[0] = visible[in[0]];
          px[1] = px[2] = meanOf[in[1]];
          px[3] = visible[in[2]];
          t.coveredWith[in[1]] += in[2] > 127;
          t.gaveUp += in[3] > 127;
        }
      }
    };
    std::vector<std::thread> pool;
    for (int band = 1; band < bands; ++band) pool.emplace_back(decode, band);
    decode(0);
    for (auto& thread : pool) thread.join();
  });
  double seSum = 0.0, covered = 0.0;
  gaveUp_ = 0;
  for (const Band& t : tally) {
    gaveUp_ += t.gaveUp;
    for (int c = 0; c < 256; ++c) {
      const double mean = double(std::min(c, n)) / double(n);  // samples are 0 or 1: the mean square is the mean
      if (n > 1) seSum += double(t.coveredWith[size_t(c)]) * std::sqrt(mean * (1.0 - mean) / double(n - 1));
      covered += double(t.coveredWith[size_t(c)]);
    }
  }
  if (standardError) *standardError = covered > 0 ? seSum / covered : 0.0;
  return out;
}

}  // namespace shadelab

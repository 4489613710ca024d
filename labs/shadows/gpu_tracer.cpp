#include "labs/shadows/gpu_tracer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>

#include "labs/shadows/ray_visibility.h"

namespace shadelab {
namespace {

constexpr int kTextureWidthLog2 = 10;  // 1024 texels per row of the BVH textures (within every GL 3.3 and WebGL2 limit)
// Disk samples a draw after the first (trace.frag's u_disks): the first pass is one sample, so
// that a whole first estimate is on screen soon where a pass is slow. A draw's rays walk the BVH
// together, so more of them a draw read the tree fewer times: 16 a draw traced the 64-sample truth
// in 0.71 of the time 8 took (llvmpipe; BM_ShadowTruth/1/1).
constexpr int kSamplesPerDraw = 16;

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

ProgramSpec GpuShadowTracer::programSpec(bool oneRay) {
  ProgramSpec spec;
  spec.name = "shadows/trace";
  spec.stages = {{GL_VERTEX_SHADER, "shadows/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "shadows/trace.frag"}};
  if (oneRay) spec.defines.emplace_back("ONE_RAY", "1");
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
  bvh_ = std::make_shared<const Bvh>(sceneTriangles(scene));
  const std::vector<glm::vec4> nodes = bvh_->nodeTexels();
  nodeCount_ = int(nodes.size() / 2);
  nodes_ = floatTexture(nodes, 1 << kTextureWidthLog2);
  triangles_ = floatTexture(bvh_->triangleTexels(), 1 << kTextureWidthLog2);
  revision_ = scene.revision;
}

void GpuShadowTracer::begin(gl::RenderTarget positions, gl::RenderTarget normals, const LightFrame& light,
                            int samplesPerAxis, float epsilon) {
  light_ = light;
  perAxis_ = light.radiusWorld > 0.0f ? std::max(samplesPerAxis, 1) : 1;
  samples_ = perAxis_ * perAxis_;
  pass_ = 0;
  bandStart_ = 0;
  epsilon_ = epsilon;
  sum_.emplace(gl::RenderTarget::create(positions.size(), GL_RGBA32F));
  positions_.emplace(std::move(positions));
  normals_.emplace(std::move(normals));
  sum_->bind();
  glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (!vao_) vao_ = gl::VertexArray::make();
}

bool GpuShadowTracer::step(ShaderLibrary& shaders, ProgramSlot& slot, double budgetMs) {
  if (!sum_ || pass_ >= samples_ || !bvh_) return false;
  const auto start = std::chrono::steady_clock::now();
  Program& prog = slot.get(shaders, programSpec(light_.radiusWorld <= 0.0f));
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
  auto since = [](auto t) { return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count(); };
  // The samples of a pass: one in the first, up to kSamplesPerDraw after it (fixed for all the
  // pass's bands, which trace the same disk points).
  const auto batchAt = [&](int pass) { return pass == 0 ? 1 : std::min(kSamplesPerDraw, samples_ - pass); };
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
    bandRowSamples_ = std::clamp(int(budgetMs / perRowSample), 4, height * kSamplesPerDraw);
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
  return pass_ < samples_;
}

ImageF GpuShadowTracer::result(double* standardError) const {
  if (!sum_) return {};
  gaveUp_ = 0;
  ImageF out{sum_->size(), sum_->readRgba()};
  const float n = float(std::max(pass_, 1));
  double seSum = 0.0, covered = 0.0;
  for (size_t i = 0; i + 3 < out.rgba.size(); i += 4) {
    float* px = &out.rgba[i];
    const float mean = px[1] / n, meanSq = px[2] / n;
    if (px[3] > 0.5f && pass_ > 1) {
      seSum += std::sqrt(std::max(0.0f, meanSq - mean * mean) / (n - 1.0f));
      covered += 1.0;
    }
    const float gaveUp = std::floor(px[3] / 1024.0f);
    gaveUp_ += gaveUp > 0.0f;
    px[1] = px[2] = mean;
    px[3] = px[3] - 1024.0f * gaveUp > 0.5f ? 1.0f : 0.0f;
  }
  if (standardError) *standardError = covered > 0 ? seSum / covered : 0.0;
  return out;
}

}  // namespace shadelab

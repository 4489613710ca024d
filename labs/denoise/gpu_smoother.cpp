#include "labs/denoise/gpu_smoother.h"

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstring>

#include "app/gl/gl.h"

namespace shadelab {
namespace {

constexpr int kListWidth = 1024;           // texels per row of every texture: smooth_step.frag masks and shifts by it
constexpr double kDivergedEnergy = 100.0;  // laplacian.cpp's: 100x the start is divergence beyond doubt
// Growth is told from rounding by more than the CPU's 1e-9: float sums of a mesh's energy carry
// a few parts in a million of rounding, which would read as growth where the energy is flat.
constexpr double kGrowth = 1e-5;

enum Unit { kPositions, kRanges, kRing, kFaces };

glm::ivec2 listSize(size_t entries) { return {kListWidth, std::max(1, int((entries + kListWidth - 1) / kListWidth))}; }

gl::Texture2D integerTexture(glm::ivec2 size, GLenum internalFormat, GLenum format, std::span<const int32_t> data) {
  gl::SamplerState nearest;  // integer textures are incomplete with any filter but nearest
  nearest.minFilter = nearest.magFilter = GL_NEAREST;
  nearest.wrapS = nearest.wrapT = GL_CLAMP_TO_EDGE;
  return gl::Texture2D::fromData(size, internalFormat, format, GL_INT, data.data(), nearest);
}

gl::FramebufferName framebufferOf(GLuint texture, int level) {
  gl::FramebufferName fbo = gl::FramebufferName::make();
  glBindFramebuffer(GL_FRAMEBUFFER, fbo.get());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture, level);
  return fbo;
}

ProgramSpec stepSpec(bool alongNormal, LaplacianWeights weights, bool clampNegative) {
  ProgramSpec spec;
  spec.name = "denoise/smooth_step";
  spec.stages = {{GL_VERTEX_SHADER, "common/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "denoise/smooth_step.frag"}};
  if (alongNormal) spec.defines.emplace_back("ALONG_NORMAL", "1");
  if (weights == LaplacianWeights::Cotangent) {
    spec.name += "+cotangent";
    spec.defines.emplace_back("COTANGENT", "1");
    if (clampNegative) spec.defines.emplace_back("CLAMP_NEGATIVE", "1");
  }
  return spec;
}

// Restores the framebuffer and viewport the caller had: the smoother runs between a lab's frames.
class SavedTarget {
 public:
  SavedTarget() {
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &fbo_);
    glGetIntegerv(GL_VIEWPORT, viewport_);
  }
  ~SavedTarget() {
    glBindFramebuffer(GL_FRAMEBUFFER, GLuint(fbo_));
    glViewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
  }

 private:
  GLint fbo_ = 0, viewport_[4] = {};
};

}  // namespace

std::string GpuSmoother::unavailableReason() {
  if (!gl::esContext()) return {};
  const auto has = [](const char* name) {
    GLint count = 0;
    glGetIntegerv(GL_NUM_EXTENSIONS, &count);
    for (GLint i = 0; i < count; ++i)
      if (std::strcmp(reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, GLuint(i))), name) == 0) return true;
    return false;
  };
  if (!has("GL_EXT_color_buffer_float"))
    return "this browser's WebGL2 cannot render into float textures (no EXT_color_buffer_float)";
  if (!has("GL_OES_texture_float_linear"))
    return "this browser's WebGL2 cannot average float textures (no OES_texture_float_linear), which the energy needs";
  return {};
}

std::vector<ProgramSpec> GpuSmoother::programSpecs() {
  std::vector<ProgramSpec> all;
  for (bool alongNormal : {true, false}) {
    all.push_back(stepSpec(alongNormal, LaplacianWeights::Uniform, true));
    for (bool clamp : {true, false}) all.push_back(stepSpec(alongNormal, LaplacianWeights::Cotangent, clamp));
  }
  return all;
}

void GpuSmoother::setMesh(size_t vertexCount, std::span<const uint32_t> indices, const Adjacency& adjacency) {
  SavedTarget saved;
  vertexCount_ = vertexCount;
  // Rows a power of two too: the mip chain's top level is then the exact average of every texel.
  size_ = {kListWidth, int(std::bit_ceil((std::max<size_t>(vertexCount, 1) + kListWidth - 1) / kListWidth))};
  const size_t texels = size_t(size_.x) * size_t(size_.y);

  // Each ring entry: the neighbour and up to two vertices opposite the edge (more only where the
  // edge is non-manifold, whose third face the CPU counts and the GPU does not).
  std::vector<int32_t> ring(size_t(listSize(adjacency.ring.size()).x * listSize(adjacency.ring.size()).y) * 4, -1);
  for (size_t k = 0; k < adjacency.ring.size(); ++k) ring[k * 4] = int32_t(adjacency.ring[k]);
  const auto slot = [&](uint32_t i, uint32_t j) -> ptrdiff_t {
    const auto begin = adjacency.ring.begin() + adjacency.offsets[i],
               end = adjacency.ring.begin() + adjacency.offsets[i + 1];
    const auto it = std::lower_bound(begin, end, j);
    return it != end && *it == j ? it - adjacency.ring.begin() : -1;
  };
  const auto addOpposite = [&](ptrdiff_t entry, uint32_t o) {
    if (entry < 0) return;
    int32_t* e = &ring[size_t(entry) * 4];
    if (e[1] < 0)
      e[1] = int32_t(o);
    else if (e[2] < 0)
      e[2] = int32_t(o);
  };
  std::vector<uint32_t> faceCount(vertexCount, 0);
  for (size_t t = 0; t + 2 < indices.size(); t += 3) {
    for (int k = 0; k < 3; ++k) {
      const uint32_t o = indices[t + size_t(k)], i = indices[t + size_t((k + 1) % 3)],
                     j = indices[t + size_t((k + 2) % 3)];
      ++faceCount[o];
      if (i == j || o == i || o == j) continue;  // as edgeWeights(): a repeated index has no angle
      addOpposite(slot(i, j), o);
      addOpposite(slot(j, i), o);
    }
  }
  // Per vertex: ring start and count, face start and count; then each incident face's other corners.
  std::vector<int32_t> ranges(texels * 4, 0);
  std::vector<uint32_t> faceStart(vertexCount + 1, 0);
  for (size_t v = 0; v < vertexCount; ++v) faceStart[v + 1] = faceStart[v] + faceCount[v];
  for (size_t v = 0; v < vertexCount; ++v) {
    ranges[v * 4 + 0] = int32_t(adjacency.offsets[v]);
    ranges[v * 4 + 1] = int32_t(adjacency.offsets[v + 1] - adjacency.offsets[v]);
    ranges[v * 4 + 2] = int32_t(faceStart[v]);
    ranges[v * 4 + 3] = int32_t(faceCount[v]);
  }
  const glm::ivec2 facesSize = listSize(faceStart[vertexCount]);
  std::vector<int32_t> faces(size_t(facesSize.x * facesSize.y) * 2, 0);
  std::vector<uint32_t> filled(faceStart.begin(), faceStart.end() - 1);
  for (size_t t = 0; t + 2 < indices.size(); t += 3)
    for (int k = 0; k < 3; ++k) {
      const uint32_t v = indices[t + size_t(k)];
      int32_t* f = &faces[size_t(filled[v]++) * 2];
      f[0] = int32_t(indices[t + size_t((k + 1) % 3)]);
      f[1] = int32_t(indices[t + size_t((k + 2) % 3)]);
    }

  ranges_ = integerTexture(size_, GL_RGBA32I, GL_RGBA_INTEGER, ranges);
  ring_ = integerTexture(listSize(adjacency.ring.size()), GL_RGBA32I, GL_RGBA_INTEGER, ring);
  faces_ = integerTexture(facesSize, GL_RG32I, GL_RG_INTEGER, faces);
  levels_ = std::bit_width(unsigned(std::max(size_.x, size_.y)));
  start_ = gl::Texture2D::allocate(size_, GL_RGBA32F);
  startFbo_ = framebufferOf(start_.id(), 0);
  current_ = -1;
  for (int k = 0; k < 2; ++k) {
    positions_[k] = gl::Texture2D::allocate(size_, GL_RGBA32F, 0);
    positionFbo_[k] = framebufferOf(positions_[k].id(), 0);
    topLevelFbo_[k] = framebufferOf(positions_[k].id(), levels_ - 1);
  }
  history_ = gl::Texture2D::allocate(listSize(size_t(kMaxIterations) + 1), GL_RGBA32F);
  historyFbo_ = framebufferOf(history_.id(), 0);
  if (!emptyVao_) emptyVao_ = gl::VertexArray::make();
}

void GpuSmoother::setStart(std::span<const glm::dvec3> start) {
  glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
  for (const glm::dvec3& p : start) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  centre_ = start.empty() ? glm::dvec3(0.0) : 0.5 * (lo + hi);
  std::vector<float> texels(size_t(size_.x) * size_t(size_.y) * 4, 0.0f);
  for (size_t v = 0; v < start.size() && v < vertexCount_; ++v) {
    const glm::dvec3 p = start[v] - centre_;
    texels[v * 4 + 0] = float(p.x);
    texels[v * 4 + 1] = float(p.y);
    texels[v * 4 + 2] = float(p.z);
  }
  glBindTexture(GL_TEXTURE_2D, start_.id());
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, size_.x, size_.y, GL_RGBA, GL_FLOAT, texels.data());
  current_ = -1;
}

void GpuSmoother::step(Program& step, float lambda, int historySlot) {
  const int next = current_ == 0 ? 1 : 0;
  glBindFramebuffer(GL_FRAMEBUFFER, positionFbo_[next].get());
  step.use();
  (current_ < 0 ? start_ : positions_[current_]).bind(kPositions);
  ranges_.bind(kRanges);
  ring_.bind(kRing);
  faces_.bind(kFaces);
  step.set("u_positions", int(kPositions));
  step.set("u_ranges", int(kRanges));
  step.set("u_ring", int(kRing));
  step.set("u_faces", int(kFaces));
  step.set("u_vertexCount", int(vertexCount_));
  step.set("u_lambda", lambda);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  current_ = next;
  if (historySlot < 0) return;
  // The mip chain's top level is the average of .w, the energy terms: copied on the GPU, no stall.
  glBindTexture(GL_TEXTURE_2D, positions_[current_].id());
  glGenerateMipmap(GL_TEXTURE_2D);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, topLevelFbo_[current_].get());
  glBindTexture(GL_TEXTURE_2D, history_.id());
  glCopyTexSubImage2D(GL_TEXTURE_2D, 0, historySlot % kListWidth, historySlot / kListWidth, 0, 0, 1, 1);
}

std::vector<float> GpuSmoother::readHistory(int count) const {
  const int rows = (count + kListWidth - 1) / kListWidth;
  std::vector<float> texels(size_t(kListWidth) * size_t(rows) * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, historyFbo_.get());
  glReadPixels(0, 0, kListWidth, rows, GL_RGBA, GL_FLOAT, texels.data());
  const double texelCount = double(size_.x) * double(size_.y);
  std::vector<float> energy(static_cast<size_t>(count));
  for (int i = 0; i < count; ++i) energy[size_t(i)] = float(double(texels[size_t(i) * 4 + 3]) * texelCount);
  return energy;
}

GpuSmoothing GpuSmoother::run(ShaderLibrary& shaders, const SmoothingSettings& s) {
  SavedTarget saved;
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glDisable(GL_CULL_FACE);
  glViewport(0, 0, size_.x, size_.y);
  glBindVertexArray(emptyVao_.get());
  const ProgramRef stepProgram = shaders.program(stepSpec(s.alongNormal, s.weights, s.clampNegative));
  if (warmed_ != stepProgram.get()) {  // a driver that compiles at the first draw does it here, untimed
    current_ = -1;
    for (int k = 0; k < 2; ++k) step(*stepProgram, 0.0f, 0);  // from the input, then from a result; the mips too
    glFinish();
    warmed_ = stepProgram.get();
  }
  const auto t0 = std::chrono::steady_clock::now();  // a program's build is not the steps' cost
  const bool taubin = s.method == SmoothingMethod::Taubin;
  const float lambda = s.lambda, mu = float(taubinMu(s));
  const int iterations = std::clamp(s.iterations, 0, kMaxIterations);
  // One iteration: the step (and Taubin's mu step), each with the normals of its input.
  const auto iterate = [&](int slot) {
    step(*stepProgram, lambda, slot);
    if (taubin) step(*stepProgram, mu, -1);
  };

  GpuSmoothing r;
  current_ = -1;
  int checked = 0;  // history entries judged so far
  // The CPU's rules over the history: energy grew; 100x the start or not finite: stop there.
  const auto judge = [&](int count) {
    const std::vector<float> history = readHistory(count);
    for (int it = checked; it < count; ++it) {
      const double e = history[size_t(it)];
      if (!std::isfinite(e)) return it - 1;  // the step before left a non-finite position: the CPU refuses it
      r.energy.push_back(e);
      if (it > 0 && r.grewAt == 0 && e > r.energy[size_t(it) - 1] * (1.0 + kGrowth)) r.grewAt = it;
      if (!(e <= kDivergedEnergy * std::max(r.energy.front(), 1e-300))) return it;
    }
    checked = count;
    return -1;
  };
  int stopped = -1;
  for (int it = 0; it < iterations && stopped < 0; ++it) {
    iterate(it);
    if ((it + 1) % kCheckEvery == 0) stopped = judge(it + 1);
  }
  if (stopped < 0) {  // the energy after the last step: a step of size 0
    step(*stepProgram, 0.0f, iterations);
    stopped = judge(iterations + 1);
    if (stopped >= iterations) stopped = -1;  // diverged at the very end: every step ran, as on the CPU
  }
  if (stopped >= 0) {  // run again to the step it stopped at: the mesh the CPU keeps
    r.stoppedAt = std::max(stopped, 0);
    current_ = -1;
    for (int it = 0; it < r.stoppedAt; ++it) iterate(-1);
  }
  glFinish();
  r.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

std::vector<glm::dvec3> GpuSmoother::readPositions() const {
  SavedTarget saved;
  std::vector<float> texels(size_t(size_.x) * size_t(size_.y) * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, current_ < 0 ? startFbo_.get() : positionFbo_[current_].get());
  glReadPixels(0, 0, size_.x, size_.y, GL_RGBA, GL_FLOAT, texels.data());
  std::vector<glm::dvec3> p(vertexCount_);
  for (size_t v = 0; v < vertexCount_; ++v)
    p[v] = centre_ + glm::dvec3(texels[v * 4], texels[v * 4 + 1], texels[v * 4 + 2]);
  return p;
}

}  // namespace shadelab

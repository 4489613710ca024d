// Explicit and Taubin Laplacian smoothing on the GPU: the steps smooth() takes on the CPU
// (laplacian.h), one fragment per vertex, so a lambda drag stays live on meshes far larger than
// the CPU can smooth between two frames.
//
// Every per-vertex value lives at texel (v % 1024, v / 1024) of a texture 1024 wide and a power of
// two high:
//   start       RGBA32F, the input, uploaded once per input (a lambda drag reuses it)
//   positions   RGBA32F, two of them (ping-pong), relative to the mesh's centre for precision; .w
//               holds the vertex's energy term of the step that wrote it, and the mip chain's top
//               level averages it: the step's energy without reading the mesh back
//   ranges      RGBA32I: where the vertex's ring and its faces start in the two lists, and their counts
//   ring        RGBA32I: each neighbour j with the vertices opposite the edge (v, j), for cotangent weights
//   faces       RG32I: each incident face's other two corners, in winding order: the step shader
//               recomputes the vertex normal from them before every step, as the CPU does
// Each step's energy is copied into a history texture on the GPU; the history is read every
// kCheckEvery steps to find divergence (growth, 100x the start, non-finite values) at the same
// step the CPU finds it. Float, not double: positions agree with the CPU's to about 1e-6 of the
// mesh's size per step (tests/gl/denoise_gpu_test.cpp measures it). Implicit smoothing and the
// bilateral filter stay on the CPU.
#pragma once
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "app/gl/handle.h"
#include "app/gl/texture.h"
#include "app/shader/shader_library.h"
#include "labs/denoise/laplacian.h"

namespace shadelab {

struct GpuSmoothing {
  std::vector<double> energy;  // as SmoothingResult's: before each iteration, and after the last
  int grewAt = 0, stoppedAt = 0;
  double ms = 0.0;  // the steps and their checks; neither the program's build nor the read-back
};

class GpuSmoother {
 public:
  static constexpr int kCheckEvery = 16;  // steps between reads of the energy history
  static constexpr int kMaxIterations = 4096;

  // "" where this context can smooth on the GPU, else why not (WebGL2 without float render targets).
  static std::string unavailableReason();
  // Every program it draws with, for check-shaders.
  static std::vector<ProgramSpec> programSpecs();

  // The connectivity, uploaded once per mesh: `indices` over `vertexCount` vertices.
  void setMesh(size_t vertexCount, std::span<const uint32_t> indices, const Adjacency& adjacency);
  // The positions smoothing starts from, one per vertex of setMesh: uploaded until the next call.
  void setStart(std::span<const glm::dvec3> start);
  // Explicit or Taubin smoothing of the start as `settings` says; the result stays on the GPU
  // until readPositions().
  GpuSmoothing run(ShaderLibrary& shaders, const SmoothingSettings& settings);
  std::vector<glm::dvec3> readPositions() const;
  // The texture the last run's result is in (.xyz relative to centre()).
  GLuint positionTexture() const { return current_ < 0 ? start_.id() : positions_[current_].id(); }
  glm::dvec3 centre() const { return centre_; }

 private:
  // One step of size `lambda` from the current positions (the start's, first) into the other
  // texture of the pair; `historySlot` >= 0 copies
  // the step's energy (the average of .w over the texture) into that texel of the history.
  void step(Program& step, float lambda, int historySlot);
  std::vector<float> readHistory(int count) const;

  size_t vertexCount_ = 0;
  glm::ivec2 size_{0};
  glm::dvec3 centre_{0.0};
  gl::Texture2D start_, positions_[2], ranges_, ring_, faces_, history_;
  gl::FramebufferName startFbo_, positionFbo_[2], topLevelFbo_[2], historyFbo_;
  gl::VertexArray emptyVao_;
  int current_ = -1;                 // which of positions_ holds the current positions; -1: start_ does
  const Program* warmed_ = nullptr;  // the program drawn once already (compiled by the driver)
  int levels_ = 1;
};

}  // namespace shadelab

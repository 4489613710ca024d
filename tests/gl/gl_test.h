#pragma once
#include <filesystem>

#include <functional>
#include <vector>

#include "context/gl_context.h"
#include "host/lab_host.h"

namespace shadelab::test {

extern GlContext* g_context;

inline ShaderSearchPath builtinShaders() {
  return ShaderSearchPath({std::filesystem::path(SHADELAB_SOURCE_DIR) / "shaders"});
}

inline std::filesystem::path testOutput(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::path(SHADELAB_TEST_OUT) / "gl";
  std::filesystem::create_directories(dir);
  return dir / name;
}

// Compares `actual` with tests/golden/<name>.png: mean error <= 0.004 and at most 0.5 % of pixels
// off by more than 0.2 (8-bit quantisation alone gives 1/510; llvmpipe on other CPUs and LLVMs
// moves a few edge pixels, hence a loose max and a tight mean). On failure the actual image and an
// amplified diff land in build/test-output/gl/. SHADELAB_UPDATE_GOLDEN=1 rewrites the golden.
void expectGolden(const std::string& name, const ImageF& actual);

// Runs the vertex stage `relPath` (built-in shaders, with `defines`) over every vertex of `mesh`
// as points and returns the vec3 varying `varying` it wrote, per vertex, by transform feedback:
// what a displacement shader really did, to compare with the CPU's account of it.
// `uniforms` sets the program's uniforms (the program is bound when it runs).
std::vector<glm::vec3> captureVertexOutput(const std::string& relPath, const Defines& defines, const char* varying,
                                           const GpuMesh& mesh, const std::function<void(GLuint)>& uniforms);

}  // namespace shadelab::test

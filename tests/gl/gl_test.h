#pragma once
#include <filesystem>

#include <cmath>
#include <functional>
#include <memory>
#include <string>

#include <gtest/gtest.h>
#include <vector>

#include "app/context/gl_context.h"
#include "app/host/lab_host.h"

namespace shadelab::test {

extern GlContext* g_context;

inline ShaderSearchPath builtinShaders() {
  return ShaderSearchPath({std::filesystem::path(SHADELAB_SOURCE_DIR) / "shaders"});
}

// A lab on one of its scenes with `sets` ("lab.key=value") applied; each must be accepted.
inline std::unique_ptr<LabHost> labHost(const char* lab, const char* scene, const std::vector<std::string>& sets) {
  auto host = std::make_unique<LabHost>(builtinShaders());
  EXPECT_EQ(host->selectLab(lab), "");
  if (scene) EXPECT_EQ(host->selectScene(scene), "");
  for (auto& s : sets) EXPECT_EQ(host->set(s), "") << s;
  return host;
}

// One of a measurement's values by name; a missing one fails the test.
inline double metric(const Metrics& m, const char* key) {
  for (auto& [k, v] : m)
    if (k == key) return v;
  ADD_FAILURE() << "no metric " << key;
  return NAN;
}

// Whether any of the lab's warnings contains `words`.
inline bool warns(const Lab& lab, const std::string& words) {
  for (auto& w : lab.warnings())
    if (w.find(words) != std::string::npos) return true;
  return false;
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

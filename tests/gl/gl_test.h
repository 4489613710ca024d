#pragma once
#include <filesystem>

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

}  // namespace shadelab::test

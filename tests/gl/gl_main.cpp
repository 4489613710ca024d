// One headless context for the whole GL test binary, made current before any test runs: OSMesa, or
// SHADELAB_BACKEND=egl to run the suite on a GPU (golden images are llvmpipe's and may differ there);
// EGL too in a build without OSMesa.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "app/util/process_memory.h"
#include "gl_test.h"

namespace shadelab::test {
GlContext* g_context = nullptr;
}

int main(int argc, char** argv) {
  shadelab::keepLargeBlocksApart();  // the allocator as the application sets it
  ::testing::InitGoogleTest(&argc, argv);
  const char* chosen = std::getenv("SHADELAB_BACKEND");
  const std::string backend = chosen ? chosen : "osmesa";
  if (backend == "osmesa") setenv("LIBGL_ALWAYS_SOFTWARE", "1", 0);
  std::string err;
  auto context = shadelab::createHeadlessContext(backend, err);
  if (!context && !chosen) context = shadelab::createHeadlessContext("egl", err);  // a build without OSMesa
  if (!context) {
    std::fprintf(stderr, "gl_tests: %s\n", err.c_str());
    return 1;
  }
  shadelab::test::g_context = context.get();
  return RUN_ALL_TESTS();
}

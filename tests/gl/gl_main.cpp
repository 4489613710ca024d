// One OSMesa context for the whole GL test binary, made current before any test runs.
#include <gtest/gtest.h>

#include <cstdlib>

#include "gl_test.h"

namespace shadelab::test {
GlContext* g_context = nullptr;
}

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  setenv("LIBGL_ALWAYS_SOFTWARE", "1", 0);
  std::string err;
  auto context = shadelab::createHeadlessContext("osmesa", err);
  if (!context) {
    std::fprintf(stderr, "gl_tests: %s\n", err.c_str());
    return 1;
  }
  shadelab::test::g_context = context.get();
  return RUN_ALL_TESTS();
}

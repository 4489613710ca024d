// Golden images of the shading lab. On failure the actual image and an amplified diff are
// written to build/test-output/gl/. SHADELAB_UPDATE_GOLDEN=1 rewrites the goldens instead.
#include <gtest/gtest.h>

#include <cstdlib>

#include "gl_test.h"

using namespace shadelab;

struct GoldenCase {
  const char* name;
  const char* scene;
  std::vector<std::string> sets;
};

class Golden : public ::testing::TestWithParam<GoldenCase> {};

TEST_P(Golden, MatchesWithinTolerance) {
  const GoldenCase& c = GetParam();
  LabHost host(test::builtinShaders());
  ASSERT_EQ(host.selectScene(c.scene), "");
  for (auto& s : c.sets) ASSERT_EQ(host.set(s), "");
  host.renderFrame({256, 144});
  const ImageF actual = host.readImage();
  ASSERT_EQ(countNonFinite(actual), 0u);
  const std::string golden = std::string(SHADELAB_GOLDEN_DIR) + "/" + c.name + ".png";
  if (std::getenv("SHADELAB_UPDATE_GOLDEN")) {
    ASSERT_EQ(writePng(golden, actual), "");
    GTEST_SKIP() << "updated " << golden;
  }
  ImageF expected;
  ASSERT_EQ(readImage(golden, expected), "") << "run with SHADELAB_UPDATE_GOLDEN=1 to create it";
  // 8-bit quantisation of the golden alone gives 1/510; llvmpipe on other CPUs/LLVMs moves
  // a few edge pixels, hence a loose max and a tight mean.
  const ImageError e = compareImages(actual, expected, 0.2);
  if (e.meanError > 0.004 || e.badPixelPct > 0.5) {
    writePng(test::testOutput(std::string(c.name) + "_actual.png"), actual);
    writePng(test::testOutput(std::string(c.name) + "_diff.png"), diffImage(actual, expected));
  }
  EXPECT_LE(e.meanError, 0.004) << c.name;
  EXPECT_LE(e.badPixelPct, 0.5) << c.name;
}

INSTANTIATE_TEST_SUITE_P(
    Shading, Golden,
    ::testing::Values(GoldenCase{"shading_phong", "shading", {}},
                      GoldenCase{"shading_gouraud_affine", "shading",
                                 {"shading.mode=gouraud", "shading.uv_interpolation=affine", "shading.tessellation=8"}},
                      GoldenCase{"shading_flat_phong_specular", "shading",
                                 {"shading.mode=flat", "shading.specular=phong", "shading.lights=4"}},
                      GoldenCase{"shading_cube_no_lights", "cube", {"shading.lights=0", "shading.ka=0.8"}}),
    [](const auto& info) { return std::string(info.param.name); });

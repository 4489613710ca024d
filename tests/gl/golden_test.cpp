// Golden images of the shading lab (tolerances and updating: test::expectGolden in gl_test.h).
#include <gtest/gtest.h>

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
  test::expectGolden(c.name, host.readImage());
}

INSTANTIATE_TEST_SUITE_P(
    Shading, Golden,
    ::testing::Values(GoldenCase{"shading_phong", "shading", {}},
                      GoldenCase{"shading_gouraud_affine",
                                 "shading",
                                 {"shading.mode=gouraud", "shading.uv_interpolation=affine", "shading.tessellation=8"}},
                      GoldenCase{"shading_flat_phong_specular",
                                 "shading",
                                 {"shading.mode=flat", "shading.specular=phong", "shading.lights=4"}},
                      GoldenCase{"shading_cube_no_lights", "cube", {"shading.lights=0", "shading.ka=0.8"}}),
    [](const auto& info) { return std::string(info.param.name); });

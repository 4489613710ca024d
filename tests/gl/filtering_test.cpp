// The texture-filtering lab on OSMesa: the shader's bilinear filter is the hardware's within one
// 8-bit step; the supersampled reference has converged at 16 x 16 samples; on the grazing plane
// error falls nearest > bilinear > trilinear > anisotropic; the footprint read back matches the
// projection's; only the images a drawn material uses are decoded; extreme sizes stay finite; a
// golden image per filter.
#include <gtest/gtest.h>

#include <cmath>

#include "app/host/measurer.h"
#include "gl_test.h"
#include "labs/filtering/filtering_lab.h"

using namespace shadelab;

namespace {

std::unique_ptr<LabHost> filteringHost(const std::vector<std::string>& sets, const char* scene = "grazing-tiles") {
  return test::labHost("filtering", scene, sets);
}

// The largest difference of any channel over the pixels both images cover.
float maxCoveredDifference(const ImageF& a, const ImageF& b) {
  float worst = 0.0f;
  for (size_t i = 0; i < a.rgba.size(); i += 4) {
    if (a.rgba[i + 3] < 0.5f || b.rgba[i + 3] < 0.5f) continue;
    for (size_t c = 0; c < 3; ++c) worst = std::max(worst, std::abs(a.rgba[i + c] - b.rgba[i + c]));
  }
  return worst;
}

}  // namespace

TEST(Filtering, ShaderBilinearEqualsHardwareBilinearWhenMagnified) {
  // 16 x 16 texels over about 300 pixels: every pixel between four texel centres.
  auto host = filteringHost({"filtering.filter=bilinear", "filtering.footprint_probe=off"}, "magnify");
  host->renderFrame({320, 240});
  const ImageF hardware = host->readImage();
  host->set("filtering.in_shader=on");
  host->renderFrame({320, 240});
  const ImageF shader = host->readImage();
  EXPECT_GT(compareImages(hardware, shader).coveredPct, 50.0);
  EXPECT_LE(maxCoveredDifference(hardware, shader), 1.0f / 255.0f + 1e-4f);
  // ... and nearest against nearest exactly, but for texel boundaries that round differently.
  host->set("filtering.filter=nearest");
  host->renderFrame({320, 240});
  const ImageF nearestShader = host->readImage();
  host->set("filtering.in_shader=off");
  host->renderFrame({320, 240});
  EXPECT_LT(compareImages(host->readImage(), nearestShader, 0.02).badPixelPct, 1.0);
  EXPECT_EQ(gl::drainErrors(), "");
}

TEST(Filtering, ShaderTrilinearIsCloseToHardwareTrilinear) {
  // The level of detail is where implementations may differ (the spec allows approximations of
  // the footprint's length): close, not equal.
  auto host = filteringHost({"filtering.footprint_probe=off"});
  host->renderFrame({320, 180});
  const ImageF hardware = host->readImage();
  host->set("filtering.in_shader=on");
  host->renderFrame({320, 180});
  const double rmse = compareImages(hardware, host->readImage()).coveredRmse;
  EXPECT_LT(rmse, 0.01);
  std::printf("shader trilinear against hardware: covered RMSE %.5f\n", rmse);
}

TEST(Filtering, TheReferenceHasConvergedAt16x16Samples) {
  auto host = filteringHost({});
  host->renderFrame({160, 90});
  const ReferenceSpec spec = host->lab().judge()->reference();
  ASSERT_EQ(spec.jitterGrid, 16);
  host->applySettings(spec.overrides);
  const gl::RenderTarget target = gl::RenderTarget::create({160, 90});
  auto accumulate = [&](int grid) {
    ImageAccumulator acc(true);
    for (const JitterSample& s : jitterSamples(grid, PixelFilter::Box)) {
      host->drawInto(target, host->camera(), 0.0f, s.offset);
      acc.add({target.size(), target.readRgba()}, s.weight);
    }
    return acc.mean();
  };
  const ImageF fine = accumulate(32), reference = accumulate(16), coarse = accumulate(4);
  const double converged = compareImages(reference, fine).coveredRmse;
  EXPECT_LT(converged, 0.008) << "16 x 16 against 32 x 32";
  std::printf("reference 16x16 against 32x32: covered RMSE %.5f\n", converged);
  EXPECT_GT(compareImages(coarse, fine).coveredRmse, 2.0 * converged) << "4 x 4 is visibly short of it";
}

TEST(Filtering, ErrorFallsFromNearestToBilinearToTrilinearToAnisotropic) {
  auto host = filteringHost({});
  Measurer measurer(*host);
  const std::vector<std::pair<const char*, std::vector<std::string>>> filters = {
      {"nearest", {"filtering.filter=nearest", "filtering.mipmaps=off"}},
      {"bilinear", {"filtering.filter=bilinear", "filtering.mipmaps=off"}},
      {"trilinear", {"filtering.filter=bilinear", "filtering.mipmaps=linear-level"}},
      {"anisotropic 16x", {"filtering.anisotropy=16"}}};
  double previousRmse = INFINITY, previousFlicker = INFINITY;
  for (auto& [name, sets] : filters) {
    for (auto& s : sets) ASSERT_EQ(host->set(s), "");
    host->renderFrame({320, 180});
    auto m = measurer.measureNow({320, 180}, 0.0f, {{"gpu_ms", 1.0}});
    ASSERT_TRUE(m);
    const double rmse = test::metric(m->values, "rmse"), flicker = test::metric(m->values, "flicker");
    EXPECT_LT(rmse, previousRmse) << name;
    EXPECT_LT(flicker, previousFlicker) << name;
    EXPECT_NEAR(test::metric(m->values, "psnr_db"), -20.0 * std::log10(rmse), 1e-6);
    previousRmse = rmse;
    previousFlicker = flicker;
  }
}

TEST(Filtering, TheFootprintIsTheProjectionsDerivative) {
  // The zone plate's 1024 texels span a 2-unit quad facing the camera: one pixel right moves u by
  // 1024 / (the quad's width in pixels) texels and v not at all.
  auto host = filteringHost({"filtering.probe_x=0.5", "filtering.probe_y=0.5"}, "zoneplate");
  host->renderFrame({320, 240});
  auto& lab = static_cast<FilteringLab&>(host->lab());
  const Footprint& f = lab.footprint();
  ASSERT_TRUE(f.covered);
  const glm::mat4 vp = host->camera().projection(320.0f / 240.0f) * host->camera().view();
  const glm::vec4 a = vp * glm::vec4(-1, 0, 0, 1), b = vp * glm::vec4(1, 0, 0, 1);
  const float quadPixels = (b.x / b.w - a.x / a.w) * 0.5f * 320.0f;
  EXPECT_NEAR(f.dx.x, 1024.0f / quadPixels, 0.02f * 1024.0f / quadPixels);
  EXPECT_NEAR(f.dy.y, 1024.0f / quadPixels, 0.02f * 1024.0f / quadPixels);
  EXPECT_NEAR(f.dx.y, 0.0f, 1e-3f);
  EXPECT_NEAR(f.dy.x, 0.0f, 1e-3f);
}

TEST(Filtering, OnlyTheImagesADrawnMaterialUsesAreDecoded) {
  auto host = filteringHost({"filtering.downsampler=kaiser"}, "unused-texture");
  host->renderFrame({64, 48});
  auto& lab = static_cast<FilteringLab&>(host->lab());
  EXPECT_EQ(lab.imagesDecoded(), 1) << "the unused image (a missing file) was decoded";
  for (auto& w : host->warnings()) EXPECT_EQ(w.find("unused.png"), std::string::npos) << w;
  host->set("filtering.downsampler=box");  // a new chain from the decoded level 0, not a new decode
  host->renderFrame({64, 48});
  EXPECT_EQ(lab.imagesDecoded(), 1);
  EXPECT_EQ(host->gpuScene().texturesUploaded(), 0) << "the host uploaded textures the lab builds itself";
}

TEST(Filtering, ExtremeSizesAndDerivativesStayFinite) {
  const std::vector<std::pair<const char*, std::vector<std::string>>> cases = {
      {"one-texel", {"filtering.filter=bicubic", "filtering.anisotropy=16"}},
      {"npot", {"filtering.in_shader=on", "filtering.downsampler=kaiser"}},
      {"constant-uv", {"filtering.in_shader=on", "filtering.view=mip-level"}},
      {"huge-uv", {"filtering.in_shader=on", "filtering.anisotropy=16"}},
      {"horizon", {"filtering.lod_bias=-16", "filtering.in_shader=on"}}};
  for (auto& [scene, sets] : cases) {
    auto host = filteringHost(sets, scene);
    host->renderFrame({160, 90});
    EXPECT_EQ(countNonFinite(host->readImage()), 0u) << scene;
  }
}

struct FilteringGolden {
  const char* name;
  std::vector<std::string> sets;
  const char* scene = "grazing-tiles";
};

class FilteringGoldens : public ::testing::TestWithParam<FilteringGolden> {};

TEST_P(FilteringGoldens, MatchWithinTolerance) {
  auto host = filteringHost(GetParam().sets, GetParam().scene);
  host->renderFrame({256, 144});
  test::expectGolden(GetParam().name, host->readImage());
}

INSTANTIATE_TEST_SUITE_P(
    Filtering, FilteringGoldens,
    ::testing::Values(FilteringGolden{"filtering_nearest", {"filtering.filter=nearest", "filtering.mipmaps=off"}},
                      FilteringGolden{"filtering_bilinear", {"filtering.mipmaps=off"}},
                      FilteringGolden{"filtering_mip_nearest", {"filtering.mipmaps=nearest-level"}},
                      FilteringGolden{"filtering_trilinear", {}},
                      FilteringGolden{"filtering_anisotropic", {"filtering.anisotropy=16"}},
                      FilteringGolden{"filtering_mip_level_view", {"filtering.view=mip-level"}},
                      FilteringGolden{"filtering_bicubic_magnified", {"filtering.filter=bicubic"}, "magnify"}));

// llvmpipe's own anisotropic probes slow about twice for each level read finer than the footprint
// (seconds a frame at a LOD bias of -6 or a chosen level 0): there the lab draws its own probes in
// the shader and says so; a GPU's driver keeps them.
TEST(Filtering, AnisotropyAtFineLevelsLeavesLlvmpipesProbesForTheShaders) {
  for (const char* fine : {"filtering.lod_bias=-6", "filtering.manual_level=on"}) {
    auto host = filteringHost({"filtering.anisotropy=16", fine});
    const auto& passes = host->renderFrame({160, 90});
    ASSERT_FALSE(passes.empty());
    const bool llvmpipe = gl::rendererIs("llvmpipe");
    bool said = false;
    for (const std::string& w : host->warnings()) said |= w.find("probes are the shader's") != std::string::npos;
    EXPECT_EQ(said, llvmpipe) << fine;
    EXPECT_EQ(passes.front().name.find("in shader") != std::string::npos, llvmpipe)
        << fine << ": " << passes.front().name;
    EXPECT_EQ(countNonFinite(host->readImage()), 0u);
  }
  auto host = filteringHost({"filtering.anisotropy=16"});  // at the footprint's own levels the driver's probes serve
  const auto& passes = host->renderFrame({160, 90});
  ASSERT_FALSE(passes.empty());
  EXPECT_EQ(passes.front().name.find("in shader"), std::string::npos) << passes.front().name;
}

// Truths are cached for the lab in use only: a lab switch lets them go (a full-HD view's eight
// are 265 MB), as it lets the last lab's measurements go. So does leaving the lab and coming back
// before anything asked the measurer (a window on a lab without a truth never does).
TEST(Filtering, ALabSwitchLetsTheCachedTruthsGo) {
  auto host = filteringHost({});
  Measurer measurer(*host);
  auto measure = [&] {
    host->renderFrame({160, 90});
    ASSERT_TRUE(measurer.measureNow({160, 90}, 0.0f, {{"gpu_ms", 1.0}}));
    EXPECT_GE(measurer.cachedTruths(), 1u);
    EXPECT_EQ(measurer.history().size(), 1u);
  };
  measure();
  for (const Measurement& m : measurer.history())  // the numbers are kept, not the images' memory
    EXPECT_EQ(m.image.rgba.capacity() + m.reference.rgba.capacity() + m.images.capacity() + m.references.capacity(),
              0u);
  ASSERT_EQ(host->selectLab("shading"), "");
  host->renderFrame({160, 90});
  EXPECT_TRUE(measurer.history().empty());
  EXPECT_EQ(measurer.cachedTruths(), 0u);

  ASSERT_EQ(host->selectLab("filtering"), "");
  measure();
  ASSERT_EQ(host->selectLab("shading"), "");
  ASSERT_EQ(host->selectLab("filtering"), "");
  measurer.followLab();
  EXPECT_EQ(measurer.cachedTruths(), 0u);
  EXPECT_TRUE(measurer.history().empty());
}

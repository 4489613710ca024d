// The shadows lab on OSMesa: passes that run, agreement with ray-traced truth, PCSS at radius 0,
// and golden images of the main techniques.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <random>

#include "gl_test.h"
#include "labs/shadows/shadows_lab.h"

using namespace shadelab;

namespace {

std::unique_ptr<LabHost> shadowsHost(const std::vector<std::string>& sets) {
  auto host = std::make_unique<LabHost>(test::builtinShaders());
  EXPECT_EQ(host->selectLab("shadows"), "");
  for (auto& s : sets) EXPECT_EQ(host->set(s), "") << s;
  return host;
}

std::vector<std::string> passNames(LabHost& host) {
  std::vector<std::string> names;
  for (auto& p : host.lastPasses()) names.push_back(p.name);
  return names;
}

double metric(const Metrics& m, const char* key) {
  for (auto& [k, v] : m)
    if (k == key) return v;
  ADD_FAILURE() << "no metric " << key;
  return 0;
}

}  // namespace

TEST(Shadows, OnlyCastingLightsGetADepthPass) {
  auto host = shadowsHost({});
  host->renderFrame({96, 54});
  EXPECT_EQ(passNames(*host).size(), 2u);  // key map + lighting
  host->set("shadows.key_casts=off");
  host->renderFrame({96, 54});
  EXPECT_EQ(passNames(*host), std::vector<std::string>{"lighting"});
  host->set("shadows.fill_light=on");
  host->renderFrame({96, 54});
  ASSERT_EQ(passNames(*host).size(), 2u);
  EXPECT_EQ(passNames(*host)[0].rfind("shadow map: fill", 0), 0u);
  host->set("shadows.fill_casts=off");
  host->renderFrame({96, 54});
  EXPECT_EQ(passNames(*host), std::vector<std::string>{"lighting"});
  EXPECT_EQ(gl::drainErrors(), "");
}

TEST(Shadows, AgreesWithRayTracedTruthWhereTheMapIsTriviallyRight) {
  // A large map, light well above the horizon, hard shadows: only texel-sized edges can differ.
  for (const char* type : {"directional", "spot", "point"}) {
    auto host = shadowsHost({"shadows.filter=hard", "shadows.map_size=4096", "shadows.light_elevation=55",
                             std::string("shadows.light_type=") + type, "shadows.light_distance=2.5"});
    const ImageF truth = host->renderReference({192, 108});
    const ImageF map = host->renderMeasured({192, 108});
    ASSERT_EQ(countNonFinite(truth) + countNonFinite(map), 0u);
    const Metrics m = host->lab().judge()->metrics(map, truth);
    EXPECT_GT(metric(m, "valid_pct"), 20.0) << type;
    EXPECT_LT(metric(m, "misclassified_pct"), 0.5) << type;
  }
}

TEST(Shadows, NoBiasMeansAcneAndTheMetricSeesIt) {
  auto host = shadowsHost({"shadows.filter=hard", "shadows.bias=0", "shadows.slope_bias=0"});
  const ImageF truth = host->renderReference({192, 108});
  const Metrics acne = host->lab().judge()->metrics(host->renderMeasured({192, 108}), truth);
  host->set("shadows.bias=2.5");
  host->set("shadows.slope_bias=4");
  const Metrics biased = host->lab().judge()->metrics(host->renderMeasured({192, 108}), truth);
  EXPECT_GT(metric(acne, "acne_pct"), 10.0);
  EXPECT_LT(metric(biased, "acne_pct"), 0.5);
  host->set("shadows.bias=40");  // far too much: shadows detach from their casters
  const Metrics panned = host->lab().judge()->metrics(host->renderMeasured({192, 108}), truth);
  EXPECT_GT(metric(panned, "leak_pct"), metric(biased, "leak_pct"));
}

TEST(Shadows, PcssWithRadiusZeroEqualsHard) {
  for (const char* type : {"directional", "spot", "point"}) {
    auto host = shadowsHost({"shadows.filter=hard", std::string("shadows.light_type=") + type});
    host->renderFrame({160, 90});
    const ImageF hard = host->readImage();
    host->set("shadows.filter=pcss");
    host->set("shadows.light_radius=0");
    host->renderFrame({160, 90});
    const ImageError e = compareImages(host->readImage(), hard);
    EXPECT_EQ(e.maxError, 0.0) << type;
  }
}

TEST(Shadows, CubeMapInSixPassesEqualsOnePass) {
  auto host = shadowsHost({"shadows.light_type=point", "shadows.light_distance=1.2", "shadows.filter=pcf"});
  host->renderFrame({160, 90});
  const ImageF onePass = host->readImage();
  host->set("shadows.six_cube_passes=on");
  host->renderFrame({160, 90});
  EXPECT_EQ(compareImages(host->readImage(), onePass).maxError, 0.0);
  EXPECT_NE(passNames(*host)[0].find("6 passes"), std::string::npos);
  EXPECT_EQ(gl::drainErrors(), "");
}

TEST(Shadows, DepthViewShowsEitherLightsMap) {
  auto host = shadowsHost({"shadows.view=depth-linear"});
  host->renderFrame({96, 54});
  EXPECT_EQ(passNames(*host).back(), "depth map view");
  host->set("shadows.depth_light=fill");  // no fill light yet: the lab says so, nothing breaks
  host->renderFrame({96, 54});
  bool warned = false;
  for (auto& w : host->warnings()) warned |= w.find("fill light's map") != std::string::npos;
  EXPECT_TRUE(warned);
  host->set("shadows.fill_light=on");
  host->renderFrame({96, 54});
  const auto names = passNames(*host);
  EXPECT_NE(std::find_if(names.begin(), names.end(), [](auto& n) { return n.rfind("shadow map: fill", 0) == 0; }),
            names.end());
  EXPECT_EQ(countNonFinite(host->readImage()), 0u);
  EXPECT_EQ(gl::drainErrors(), "");
}

TEST(Shadows, SoftShadowsApproachTheAreaLight) {
  auto host = shadowsHost({"shadows.filter=pcss", "shadows.light_radius=0.1"});
  const ImageF truth = host->renderReference({160, 90});
  const double pcss =
      metric(host->lab().judge()->metrics(host->renderMeasured({160, 90}), truth), "visibility_rmse_area");
  host->set("shadows.filter=hard");  // the same area-light truth, judged against a hard shadow
  const double hard =
      metric(host->lab().judge()->metrics(host->renderMeasured({160, 90}), truth), "visibility_rmse_area");
  EXPECT_LT(pcss, hard);
  // ... while against the point-light truth, the hard shadow is the closer of the two.
  const double hardVsHard =
      metric(host->lab().judge()->metrics(host->renderMeasured({160, 90}), truth), "visibility_rmse_hard");
  host->set("shadows.filter=pcss");
  const double pcssVsHard =
      metric(host->lab().judge()->metrics(host->renderMeasured({160, 90}), truth), "visibility_rmse_hard");
  EXPECT_LT(hardVsHard, pcssVsHard);
}

struct ShadowGolden {
  const char* name;
  std::vector<std::string> sets;
};

class ShadowGoldens : public ::testing::TestWithParam<ShadowGolden> {};

TEST_P(ShadowGoldens, MatchWithinTolerance) {
  auto host = shadowsHost(GetParam().sets);
  host->renderFrame({256, 144});
  test::expectGolden(GetParam().name, host->readImage());
}

INSTANTIATE_TEST_SUITE_P(
    Shadows, ShadowGoldens,
    ::testing::Values(ShadowGolden{"shadows_hard", {"shadows.filter=hard"}},
                      ShadowGolden{"shadows_pcf5", {"shadows.filter=pcf", "shadows.pcf_size=5"}},
                      ShadowGolden{"shadows_pcss_spot",
                                   {"shadows.filter=pcss", "shadows.light_type=spot", "shadows.light_radius=0.1"}},
                      ShadowGolden{"shadows_point_pcf", {"shadows.light_type=point", "shadows.light_distance=1.2"}},
                      ShadowGolden{"shadows_bias_heat", {"shadows.view=bias-heat", "shadows.bias=0.5"}}),
    [](const auto& info) { return std::string(info.param.name); });

namespace {

// The GPU tracer's truth beside Embree's for the host's current configuration: the hard truths
// differ on at most 0.05 % of the pixels (edge rays the two hit tests round differently) and the
// area truths, the same 64 stratified samples traced in another order, agree within three
// standard errors (or one sample) on 99 % of the pixels.
void expectTracersAgree(LabHost& host, const std::string& name, bool penumbra) {
  ASSERT_EQ(host.set("shadows.truth_tracer=embree"), "");
  host.renderFrame({160, 90});
  const ImageF embree = host.renderReference({160, 90});
  ASSERT_EQ(host.set("shadows.truth_tracer=gpu"), "");
  const ImageF gpu = host.renderReference({160, 90});
  ASSERT_EQ(gpu.size, embree.size) << name;
  EXPECT_EQ(countNonFinite(gpu), 0u) << name;
  size_t valid = 0, hardDiffer = 0, areaAgree = 0, soft = 0;
  for (size_t i = 0; i + 3 < gpu.rgba.size(); i += 4) {
    if (embree.rgba[i + 3] < 0.5f) continue;
    ++valid;
    hardDiffer += gpu.rgba[i] != embree.rgba[i];
    const double m = embree.rgba[i + 1], se = std::sqrt(m * (1.0 - m) / 63.0);
    const double d = std::abs(double(gpu.rgba[i + 1]) - m);
    areaAgree += d <= 3.0 * se + 1e-6 || d <= 1.0 / 64.0 + 1e-6;
    soft += m > 0.0 && m < 1.0;
  }
  ASSERT_GT(valid, 1000u) << name;
  EXPECT_LE(double(hardDiffer), 5e-4 * double(valid)) << name << ": " << hardDiffer << " of " << valid;
  EXPECT_GE(double(areaAgree), 0.99 * double(valid)) << name;
  if (penumbra) EXPECT_GT(soft, 10u) << name << ": the test needs a penumbra";
}

}  // namespace

TEST(Shadows, TheGpuTracerAgreesWithEmbree) {
  struct Case {
    const char* scene;
    std::vector<std::string> sets;
    bool penumbra = true;
  };
  const Case cases[] = {{"shadow-test", {}},
                        {"learnopengl", {}},
                        {"shadow-test", {"shadows.light_type=point"}},
                        {"shadow-test", {"shadows.light_elevation=4", "shadows.light_radius=0.3"}},
                        // the light near the scene's centre (at 0 it sits inside geometry and no pixel faces it)
                        {"shadow-test", {"shadows.light_type=point", "shadows.light_distance=0.2"}, false}};
  for (const Case& c : cases) {
    std::string name = c.scene;
    for (auto& s : c.sets) name += " " + s;
    auto host = test::labHost("shadows", c.scene, c.sets);
    expectTracersAgree(*host, name, c.penumbra);
  }
  EXPECT_EQ(gl::drainErrors(), "");
}

// How the tracer cuts its work (samples a draw, rays a walk, triangles a leaf, the cone test)
// changes its speed alone: whether a ray meets a triangle is one test whatever the tree, each ray's
// answer is the one a walk of its own gives, the cone turns away only nodes no ray enters, and the sums are of 0s and
// 1s, so every shape's truth is the same to the bit, the hard ray (pass 0's first) and a last pass of fewer samples
// included.
TEST(Shadows, TheGpuTracersShapesGiveTheSameTruth) {
  for (const char* light : {"directional", "point"}) {
    auto host = test::labHost("shadows", "shadow-test",
                              {"shadows.truth_tracer=gpu", std::string("shadows.light_type=") + light});
    auto& lab = dynamic_cast<ShadowsLab&>(host->lab());
    host->renderFrame({96, 64});
    std::optional<ImageF> first;
    for (GpuTraceShape shape :
         {GpuTraceShape{16, 16, 4, false}, GpuTraceShape{16, 1, 4, false}, GpuTraceShape{8, 4, 1, true},
          GpuTraceShape{5, 3, 8, false}, GpuTraceShape{16, 16, 2, true}, GpuTraceShape{16, 1, 1, true}}) {
      lab.setTracerShape(shape);
      const ImageF truth = host->renderReference({96, 64});
      ASSERT_NE(lab.gpuTracer(), nullptr);
      EXPECT_EQ(lab.gpuTracer()->shape().walkWidth, shape.walkWidth);
      EXPECT_EQ(lab.gpuTracer()->shape().leafSize, shape.leafSize);
      ASSERT_FALSE(truth.rgba.empty());
      if (!first) {
        first = truth;
        double area = 0.0;
        for (size_t i = 1; i < truth.rgba.size(); i += 4) area += truth.rgba[i] > 0.0f && truth.rgba[i] < 1.0f;
        EXPECT_GT(area, 10.0) << light << ": the test needs a penumbra";
        continue;
      }
      EXPECT_EQ(truth.rgba, first->rgba) << light << ": " << shape.samplesPerDraw << " samples a draw, walks of "
                                         << shape.walkWidth << ", leaves of " << shape.leafSize
                                         << (shape.coneCull ? ", cone" : "");
    }
  }
  EXPECT_EQ(gl::drainErrors(), "");
}

// The split heuristic's and the hit test's hard cases, as a file on the lab's floor: one huge
// triangle over two thousand tiny ones, zero-area triangles (a point, a line), two coplanar
// overlapping quads; at scene scale 1, 1e4 and 1e6.
TEST(Shadows, TheGpuTracerHoldsOnHugeTinyDegenerateAndCoplanarTriangles) {
  const auto file = test::testOutput("tracer_stress.obj");
  {
    std::ofstream out(file);
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    int v = 0;
    auto tri = [&](glm::vec3 a, glm::vec3 b, glm::vec3 c) {
      out << "v " << a.x << " " << a.y << " " << a.z << "\nv " << b.x << " " << b.y << " " << b.z << "\nv " << c.x
          << " " << c.y << " " << c.z << "\nf " << v + 1 << " " << v + 2 << " " << v + 3 << "\n";
      v += 3;
    };
    tri({-3, 0, -1.5f}, {3, 0, -1.5f}, {0, 4, -1.5f});  // huge: a wall behind the rest
    for (int i = 0; i < 2000; ++i) {
      const glm::vec3 c(u(rng), 0.5f + 0.4f * u(rng), u(rng));
      tri(c, c + glm::vec3(0.01f, 0.0f, 0.0f), c + glm::vec3(0.0f, 0.01f, 0.01f));
    }
    tri({0.2f, 0.3f, 0.2f}, {0.2f, 0.3f, 0.2f}, {0.2f, 0.3f, 0.2f});  // a point
    tri({0, 0.2f, 0}, {0.5f, 0.2f, 0.5f}, {1, 0.2f, 1});              // a line
    for (float shift : {0.0f, 0.3f}) {                                // coplanar, overlapping
      tri({-1 + shift, 0.05f, -1}, {1 + shift, 0.05f, -1}, {1 + shift, 0.05f, 1});
      tri({-1 + shift, 0.05f, -1}, {1 + shift, 0.05f, 1}, {-1 + shift, 0.05f, 1});
    }
  }
  for (const char* scale : {"1", "10000", "1000000"}) {
    auto host = test::labHost(
        "shadows", file.c_str(),
        {std::string("shadows.scene_scale=") + scale, "shadows.scene_light=off", "shadows.light_elevation=60"});
    expectTracersAgree(*host, std::string("stress scene, scale ") + scale, false);
  }
  EXPECT_EQ(gl::drainErrors(), "");
}

// The shadows lab's CPU side: light frusta, texel sizes, warnings, Poisson disks, metrics.
#include <gtest/gtest.h>

#include <cmath>

#include "labs/shadows/light_rig.h"
#include "labs/shadows/shadows_lab.h"

using namespace shadelab;

static Bounds unitScene() {
  Bounds b;
  b.extend({-1, -1, -1});
  b.extend({1, 1, 1});
  return b;  // radius sqrt(3)
}

TEST(LightRig, DirectionalBoxContainsTheScene) {
  std::vector<std::string> w;
  LightSetup s;
  const Bounds b = unitScene();
  const LightFrame L = buildLight(s, b, w);
  for (int c = 0; c < 8; ++c) {
    const glm::vec3 p((c & 1) ? 1 : -1, (c & 2) ? 1 : -1, (c & 4) ? 1 : -1);
    const glm::vec4 clip = L.viewProj * glm::vec4(p, 1);
    for (int k = 0; k < 3; ++k) EXPECT_LE(std::abs(clip[k] / clip.w), 1.0f + 1e-5f) << c;
  }
  EXPECT_TRUE(w.empty());
  EXPECT_FLOAT_EQ(L.texelWorld(0.0f, 1024), 2.0f * L.orthoHalfExtent / 1024.0f);
}

TEST(LightRig, SpotAndPointGeometry) {
  std::vector<std::string> w;
  LightSetup s;
  s.type = LightType::Spot;
  s.distance = 3;
  const Bounds b = unitScene();
  const LightFrame spot = buildLight(s, b, w);
  EXPECT_NEAR(glm::length(spot.position - b.center()), 3.0f * b.radius(), 1e-4f);
  EXPECT_NEAR(glm::dot(spot.direction, glm::normalize(b.center() - spot.position)), 1.0f, 1e-5f);
  EXPECT_NEAR(spot.texelWorld(5.0f, 100), 2.0f * 5.0f * spot.tanHalfFov / 100.0f, 1e-5f);
  EXPECT_EQ(spot.texelWorld(0.0f, 100), spot.texelWorld(spot.nearPlane, 100));  // never below the near plane
  s.type = LightType::Point;
  const LightFrame point = buildLight(s, b, w);
  // Each cube face sees its axis direction at the face centre.
  const glm::vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (int f = 0; f < 6; ++f) {
    const glm::vec4 clip = point.faceViewProj[f] * glm::vec4(point.position + axes[f], 1.0f);
    EXPECT_NEAR(clip.x / clip.w, 0.0f, 1e-5f) << f;
    EXPECT_NEAR(clip.y / clip.w, 0.0f, 1e-5f) << f;
  }
}

TEST(LightRig, WarnsAboutDepthPrecisionAndBadPlanes) {
  std::vector<std::string> w;
  LightSetup s;
  s.type = LightType::Spot;
  s.autoFit = false;
  s.nearPlane = 1e-5f;
  s.farPlane = 10.0f;
  buildLight(s, unitScene(), w);
  ASSERT_FALSE(w.empty());
  EXPECT_NE(w[0].find("far/near ratio"), std::string::npos) << w[0];
  w.clear();
  s.nearPlane = 5;
  s.farPlane = 1;
  buildLight(s, unitScene(), w);
  EXPECT_NE(w.back().find("near plane is beyond"), std::string::npos);
}

TEST(LightRig, ExtremeScalesStayFinite) {
  for (float scale : {1e-3f, 1.0f, 1e4f}) {
    Bounds b;
    b.extend(glm::vec3(-scale));
    b.extend(glm::vec3(scale));
    for (int type = 0; type < 3; ++type) {
      std::vector<std::string> w;
      LightSetup s;
      s.type = LightType(type);
      const LightFrame L = buildLight(s, b, w);
      for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
          EXPECT_TRUE(std::isfinite(L.viewProj[i][j])) << scale << " type " << type;
          EXPECT_TRUE(std::isfinite(L.faceViewProj[0][i][j]));
        }
      EXPECT_GT(L.nearPlane, 0.0f);
      EXPECT_LT(L.nearPlane, L.farPlane);
    }
  }
}

TEST(PoissonDisk, DeterministicInsideTheDiskAndSpread) {
  for (int n : {8, 16, 32, 64}) {
    const auto a = poissonDisk(n), b = poissonDisk(n);
    ASSERT_EQ(a.size(), size_t(n));
    EXPECT_EQ(a, b);
    float minDist = 10;
    for (size_t i = 0; i < a.size(); ++i) {
      EXPECT_LE(glm::length(a[i]), 1.0f);
      for (size_t j = i + 1; j < a.size(); ++j) minDist = std::min(minDist, glm::distance(a[i], a[j]));
    }
    EXPECT_GT(minDist, 0.8f / std::sqrt(float(n))) << n;  // no clumps
  }
}

TEST(ShadowMetrics, CountsMisclassifiedAcneAndLeaks) {
  ShadowsLab lab;
  ImageF img, ref;
  img.size = ref.size = {5, 1};
  // The truth holds the point light's visibility in R and the area light's in G.
  //            lit/lit      acne         leak         shadow/shadow  background (ignored)
  img.rgba = {1, 1, 1, 1, 0, 0, 0, 1, 1, 1, 1, 1, 0, 0, 0, 1, 0, 0, 0, 0};
  ref.rgba = {1, 1, 1, 1, 1, 1, 1, 1, 0, 0.5f, 0.5f, 1, 0, 0, 0, 1, 1, 1, 1, 0};
  const Metrics m = lab.metrics(img, ref);
  auto get = [&](const char* k) {
    for (auto& [key, v] : m)
      if (key == k) return v;
    return -1.0;
  };
  EXPECT_NEAR(get("misclassified_pct"), 100.0 * 2 / 4, 1e-9);  // of the pixels that face the light
  EXPECT_NEAR(get("acne_pct"), 100.0 / 2, 1e-9);               // of the truly lit pixels
  EXPECT_NEAR(get("leak_pct"), 100.0 / 2, 1e-9);               // of the truly shadowed pixels
  EXPECT_NEAR(get("visibility_rmse_hard"), std::sqrt(2.0 / 4), 1e-6);
  EXPECT_NEAR(get("visibility_rmse_area"), std::sqrt((1 + 0.25) / 4), 1e-6);
  EXPECT_NEAR(get("valid_pct"), 80.0, 1e-9);
  // The CSV says what each is divided by.
  for (const char* key :
       {"misclassified_pct", "acne_pct", "leak_pct", "visibility_rmse_hard", "visibility_rmse_area"}) {
    const Settings notes = lab.metricNotes();
    EXPECT_TRUE(std::any_of(notes.begin(), notes.end(), [&](auto& n) { return n.first == key; })) << key;
  }
}

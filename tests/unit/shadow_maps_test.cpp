// The shadows lab's maps on the CPU side: fitted and cascaded directional maps, texel snapping,
// the Poisson sets the shaders get, and the variant cover check-shaders compiles.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

#include <glm/gtc/matrix_transform.hpp>

#include "app/lab/variants.h"
#include "labs/shadows/light_rig.h"
#include "labs/shadows/shadows_lab.h"

using namespace shadelab;

namespace {

// The learnopengl scene's bounds and camera, as the lab builds them.
Bounds floorAndCubes() {
  Bounds b;
  b.extend({-25.0f, -0.5f, -25.0f});
  b.extend({25.0f, 2.0f, 25.0f});
  return b;
}

ViewVolume camera(glm::vec3 eye, glm::vec3 target, float aspect = 4.0f / 3.0f) {
  ViewVolume v;
  v.eye = eye;
  v.forward = glm::normalize(target - eye);
  v.nearPlane = 0.1f;
  v.farPlane = 100.0f;
  const glm::mat4 proj = glm::perspective(glm::radians(45.0f), aspect, v.nearPlane, v.farPlane);
  v.inverseViewProj = glm::inverse(proj * glm::lookAt(eye, target, glm::vec3(0, 1, 0)));
  return v;
}

LightFrame sceneFit(const Bounds& b) {
  LightSetup s;
  s.fromPoint = {-2.0f, 4.0f, -1.0f};
  std::vector<std::string> w;
  return buildLight(s, b, w);
}

}  // namespace

TEST(PoissonDisk, EveryCountIsWellSpreadAndNoPrefixIsUsed) {
  for (int n : {8, 16, 32, 64}) {
    const auto& used = ShadowsLab::disk(n);  // what the lab uploads for n taps
    ASSERT_EQ(used.size(), size_t(n));
    EXPECT_EQ(used, poissonDisk(n));
    const float ratio = minimumSpacing(used) / spacingBound(n);
    std::printf("disk %2d: minimum spacing %.3f, %.2f of the packing bound %.3f\n", n, minimumSpacing(used), ratio,
                spacingBound(n));
    EXPECT_GT(ratio, 0.6f) << n;  // well spread: a good fraction of what any n points can do
    for (auto& p : used) EXPECT_LE(glm::length(p), 1.0f + 1e-6f);
  }
  // The first 8 points of the 64-point set: what the shaders used to take for 8 taps.
  const auto& big = ShadowsLab::disk(64);
  const std::vector<glm::vec2> prefix(big.begin(), big.begin() + 8);
  EXPECT_LT(minimumSpacing(prefix), 0.75f * minimumSpacing(ShadowsLab::disk(8)));
}

TEST(Variants, PairwiseCoverHoldsEveryPairOnce) {
  const std::vector<int> sizes = {3, 7, 2, 4, 5};
  const auto rows = pairwiseCover(sizes);
  for (size_t a = 0; a < sizes.size(); ++a)
    for (size_t b = a + 1; b < sizes.size(); ++b)
      for (int i = 0; i < sizes[a]; ++i)
        for (int j = 0; j < sizes[b]; ++j)
          EXPECT_TRUE(std::any_of(rows.begin(), rows.end(), [&](auto& r) { return r[a] == i && r[b] == j; }))
              << a << "=" << i << " " << b << "=" << j;
  EXPECT_LE(rows.size(), size_t(7 * 5 + 10));  // near the 35 the two largest need, far below 840
  EXPECT_EQ(pairwiseCover(sizes), rows);       // deterministic
}

// Every value of every parameter that can be selected (bools, choices, small int ranges) changes
// nothing, or picks programs check-shaders compiles: the parameter list decides, not a hand list.
TEST(Variants, EverySingleParameterChangeIsCompiledByCheckShaders) {
  ShadowsLab lab;
  std::set<std::string> compiled;
  for (auto& spec : lab.allPrograms()) compiled.insert(spec.key());
  struct Knob {
    std::string key;
    int* i = nullptr;
    bool* b = nullptr;
    int lo = 0, hi = 0;
  };
  struct Collect final : ParamVisitor {
    std::vector<Knob> knobs;
    void floatParam(const ParamInfo&, float&, float, float, bool) override {}
    void intParam(const ParamInfo& info, int& v, int lo, int hi) override {
      if (hi - lo <= 16) knobs.push_back({std::string(info.key), &v, nullptr, lo, hi});
    }
    void boolParam(const ParamInfo& info, bool& v) override {
      knobs.push_back({std::string(info.key), nullptr, &v, 0, 1});
    }
    void choiceParam(const ParamInfo& info, int& v, std::span<const std::string_view> names) override {
      knobs.push_back({std::string(info.key), &v, nullptr, 0, int(names.size()) - 1});
    }
  } collect;
  lab.visitParams(collect);
  ASSERT_GT(collect.knobs.size(), 20u);
  int checked = 0;
  for (auto& k : collect.knobs)
    for (int v = k.lo; v <= k.hi; ++v) {
      lab.resetParams();
      if (k.i)
        *k.i = v;
      else
        *k.b = v != 0;
      for (auto& spec : lab.currentPrograms()) {
        EXPECT_TRUE(compiled.count(spec.key())) << k.key << "=" << v << ": " << spec.key();
        ++checked;
      }
    }
  EXPECT_GT(checked, 300);
}

TEST(Cascades, PracticalSplitsRunFromNearToFar) {
  const auto uniform = practicalSplits(4, 1.0f, 101.0f, 0.0f);
  const auto logarithmic = practicalSplits(4, 1.0f, 10000.0f, 1.0f);
  ASSERT_EQ(uniform.size(), 5u);
  for (int i = 0; i <= 4; ++i) {
    EXPECT_NEAR(uniform[size_t(i)], 1.0f + 25.0f * float(i), 1e-3f);
    EXPECT_NEAR(logarithmic[size_t(i)], std::pow(10.0f, float(i)), 1e-2f * std::pow(10.0f, float(i)));
  }
  const auto mixed = practicalSplits(3, 0.1f, 50.0f, 0.75f);
  EXPECT_TRUE(std::is_sorted(mixed.begin(), mixed.end()));
  EXPECT_EQ(mixed.front(), 0.1f);
  EXPECT_EQ(mixed.back(), 50.0f);
}

TEST(Cascades, CoverEveryVisiblePointWithNoGap) {
  const Bounds b = floorAndCubes();
  const LightFrame base = sceneFit(b);
  for (int count = 1; count <= 4; ++count)
    for (glm::vec3 eye : {glm::vec3(0, 3, 7), glm::vec3(-6, 1, 4), glm::vec3(20, 10, 20)}) {
      const ViewVolume view = camera(eye, glm::vec3(0, 0, 0.5f));
      const auto cascades = buildCascades(base, {count, 0.75f, 0.1f, true, 512}, view, b);
      ASSERT_EQ(int(cascades.size()), count);
      // Points spread through the frustum; those inside the scene must fall in their cascade's map.
      uint32_t state = 12345u;
      auto rnd = [&] { return float((state = state * 1664525u + 1013904223u) >> 8) / 16777216.0f; };
      int inside = 0;
      for (int k = 0; k < 20000; ++k) {
        // Uniform in depth (NDC z would crowd the points next to the near plane) and across the image.
        const auto slice = frustumSlice(view, 0.1f + 60.0f * rnd(), 1.0f);
        const float u = rnd(), v = rnd();
        const glm::vec3 p = glm::mix(glm::mix(slice[0], slice[1], u), glm::mix(slice[2], slice[3], u), v);
        if (glm::any(glm::lessThan(p, b.min)) || glm::any(glm::greaterThan(p, b.max))) continue;
        ++inside;
        const float depth = glm::dot(p - view.eye, view.forward);
        size_t c = 0;
        while (c + 1 < cascades.size() && depth > cascades[c].splitFar) ++c;
        for (size_t use = c; use <= std::min(c + 1, cascades.size() - 1); ++use) {
          if (use > c && depth <= cascades[c].blendFrom) break;  // the next one is used only in the blend band
          const glm::vec4 clip = cascades[use].light.viewProj * glm::vec4(p, 1.0f);
          for (int axis = 0; axis < 3; ++axis)
            ASSERT_LE(std::abs(clip[axis]), 1.0f + 1e-4f) << "cascade " << use << " of " << count << " misses a point"
                                                          << " axis " << axis << " eye " << eye.x << " depth " << depth
                                                          << " p " << p.x << "," << p.y << "," << p.z;
        }
      }
      EXPECT_GT(inside, 500);
    }
}

// The lit shader rebuilds each cascade's matrix from the first one's and four numbers
// (cascadeLight in shaders/shadows/lit.frag); done here the same way, it is the cascade's own.
TEST(Cascades, BoxRebuildsEachCascadesMatrixFromTheFirst) {
  const Bounds b = floorAndCubes();
  const LightFrame base = sceneFit(b);
  for (glm::vec3 eye : {glm::vec3(0, 3, 7), glm::vec3(-6, 1, 4), glm::vec3(20, 10, 20)}) {
    const auto cascades = buildCascades(base, {4, 0.75f, 0.1f, true, 1024}, camera(eye, {0, 0, 0.5f}), b);
    for (const Cascade& c : cascades) {
      const glm::vec4 box = cascadeBox(cascades[0].light, c.light);
      glm::mat4 m = cascades[0].light.viewProj;
      for (int col = 0; col < 3; ++col) m[col] = glm::vec4(glm::vec2(m[col]) * box.x, m[col].z, m[col].w);
      m[3] = glm::vec4(glm::vec2(m[3]) * box.x + glm::vec2(box.y, box.z), m[3].z, m[3].w);
      for (int col = 0; col < 4; ++col)
        for (int row = 0; row < 4; ++row)
          EXPECT_NEAR(m[col][row], c.light.viewProj[col][row], 1e-5f * (1.0f + std::abs(c.light.viewProj[col][row])))
              << "column " << col << " row " << row;
      EXPECT_EQ(box.w, c.light.orthoHalfExtent);
    }
  }
}

TEST(Cascades, ViewFitIsTighterThanTheScene) {
  const Bounds b = floorAndCubes();
  const LightFrame base = sceneFit(b);
  const ViewVolume view = camera({0, 3, 7}, {0, 0, 0.5f});
  const auto one = buildCascades(base, {1, 0.75f, 0.1f, true, 1024}, view, b);
  const auto four = buildCascades(base, {4, 0.75f, 0.1f, true, 512}, view, b);
  EXPECT_LT(one[0].light.orthoHalfExtent, 0.75f * base.orthoHalfExtent);
  // The nearest cascade at 512^2 has finer texels than one view-fitted map at 1024^2.
  EXPECT_LT(four[0].light.texelWorld(0, 512), 0.5f * one[0].light.texelWorld(0, 1024));
}

TEST(Cascades, SnappingKeepsTheMapStillUnderASubTexelMove) {
  const Bounds b = floorAndCubes();
  const LightFrame base = sceneFit(b);
  for (bool snap : {true, false}) {
    const ViewVolume a = camera({0, 3, 7}, {0, 0, 0.5f});
    const auto before = buildCascades(base, {3, 0.75f, 0.1f, snap, 1024}, a, b);
    // Move the camera sideways by a tenth of the nearest cascade's texel.
    const glm::vec3 shift(0.1f * before[0].light.texelWorld(0, 1024), 0, 0);
    const ViewVolume moved = camera(a.eye + shift, glm::vec3(0, 0, 0.5f) + shift);
    const auto after = buildCascades(base, {3, 0.75f, 0.1f, snap, 1024}, moved, b);
    bool same = true;
    for (size_t c = 0; c < before.size(); ++c) same = same && before[c].light.viewProj == after[c].light.viewProj;
    EXPECT_EQ(same, snap) << (snap ? "snapped maps moved" : "unsnapped maps should follow the camera");
    if (!snap) continue;
    // A move of many texels moves the map by a whole number of texels.
    const glm::vec3 far(37.3f * before[0].light.texelWorld(0, 1024), 0, 0);
    const auto later =
        buildCascades(base, {3, 0.75f, 0.1f, true, 1024}, camera(a.eye + far, glm::vec3(0, 0, 0.5f) + far), b);
    if (later[0].light.orthoHalfExtent == before[0].light.orthoHalfExtent) {
      const glm::vec2 moveTexels =
          (later[0].light.orthoCentre - before[0].light.orthoCentre) / before[0].light.texelWorld(0, 1024);
      EXPECT_NEAR(moveTexels.x, std::round(moveTexels.x), 1e-2f);
      EXPECT_NEAR(moveTexels.y, std::round(moveTexels.y), 1e-2f);
    }
  }
}

TEST(Cascades, CameraThatSeesNoSceneFallsBackToTheSceneFit) {
  const Bounds b = floorAndCubes();
  const LightFrame base = sceneFit(b);
  const auto cascades = buildCascades(base, {4, 0.75f, 0.1f, true, 512}, camera({0, 300, 0}, {0, 400, 1}), b);
  ASSERT_EQ(cascades.size(), 1u);
  EXPECT_EQ(cascades[0].light.viewProj, base.viewProj);
}

// The point light's depth view shows only the cube faces that see the scene, each zoomed to it.
TEST(CubeFaceWindows, FramesOnlyTheFacesThatSeeTheBoxes) {
  Bounds below;  // a floor tile straight under the light, well inside the -Y face's view
  below.min = glm::vec3(-0.5f, -2.0f, -0.5f);
  below.max = glm::vec3(0.5f, -1.9f, 0.5f);
  const std::vector<Bounds> boxes = {below};
  const auto w = cubeFaceWindows(boxes, glm::vec3(0.0f), true);
  for (int face = 0; face < 5; ++face) EXPECT_EQ(w[size_t(face)].z, 0.0f) << "face " << face;
  // -Y sees the tile at |x|, |z| <= 0.5 / 1.9 of the face: a zoomed window around the centre.
  EXPECT_NEAR(w[5].x, 0.0f, 1e-5f);
  EXPECT_NEAR(w[5].y, 0.0f, 1e-5f);
  EXPECT_GT(w[5].z, 0.5f / 1.9f);
  EXPECT_LT(w[5].z, 0.35f);

  // A box that reaches past the light's side plane projects to the face's edge on that side.
  Bounds beside;
  beside.min = glm::vec3(-1.0f, -2.0f, 0.2f);
  beside.max = glm::vec3(1.0f, -1.0f, 3.0f);
  const auto v = cubeFaceWindows(std::vector<Bounds>{beside}, glm::vec3(0.0f), true);
  EXPECT_GT(v[1].z, 0.0f);                     // +Z sees it
  EXPECT_GT(v[5].z, 0.0f);                     // so does -Y
  EXPECT_EQ(v[4].z, 0.0f);                     // +Y does not
  EXPECT_NEAR(v[1].y - v[1].z, -1.0f, 1e-4f);  // +Z's window reaches the face's bottom edge

  // frame = false: every face whole, the plain cross.
  for (const glm::vec3& whole : cubeFaceWindows(boxes, glm::vec3(0.0f), false)) EXPECT_EQ(whole, glm::vec3(0, 0, 1));
}

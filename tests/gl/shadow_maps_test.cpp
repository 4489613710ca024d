// The shadows lab's second round on OSMesa: view-fitted and cascaded maps on LearnOpenGL's scene
// against the ray-traced truth, no gap between cascades, texel snapping, PCSS on a sloped
// receiver, filtered maps, and the sample sets the shaders really hold.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>

#include "gl_test.h"
#include "labs/shadows/shadows_lab.h"

using namespace shadelab;

namespace {

ShadowsLab& shadowsOf(LabHost& host) { return dynamic_cast<ShadowsLab&>(host.lab()); }

// The learnopengl scene as the chapter sets it up: 800x600, a 1024^2 map (per cascade: 512^2,
// the same memory over four).
double misclassified(LabHost& host, const ImageF& truth) {
  return test::metric(host.lab().judge()->metrics(host.renderMeasured({800, 600}), truth), "misclassified_pct");
}

ImageF drawn(LabHost& host, glm::ivec2 size) {
  const gl::RenderTarget target = gl::RenderTarget::create(size);
  host.drawInto(target, host.camera(), 0.0f);
  return ImageF{size, target.readRgba()};
}

std::vector<float> depthLayer(const ShadowMap& map, int layer) {
  std::vector<float> all(size_t(map.size()) * size_t(map.size()) * size_t(map.layers()));
  glBindTexture(GL_TEXTURE_2D_ARRAY, map.texture());
  glGetTexImage(GL_TEXTURE_2D_ARRAY, 0, GL_DEPTH_COMPONENT, GL_FLOAT, all.data());
  const size_t n = size_t(map.size()) * size_t(map.size());
  return {all.begin() + std::ptrdiff_t(n * size_t(layer)), all.begin() + std::ptrdiff_t(n * size_t(layer + 1))};
}

}  // namespace

// The camera sees the floor to the horizon, so a map fitted to the view still spans ~35 of the
// floor's 50 units and gains less than 2x; cascades of the same memory gain several times that.
TEST(ShadowMaps, CascadesAtLeastHalveTheErrorOnLearnOpenGlsSceneAtEqualMemory) {
  auto host = test::labHost(
      "shadows", "learnopengl",
      {"shadows.map_size=1024", "shadows.filter=hard", "shadows.fit=scene"});  // the scene opens with cascades
  const ImageF truth = host->renderReference({800, 600});
  const double scene = misclassified(*host, truth);
  host->set("shadows.fit=view");
  const double view = misclassified(*host, truth);
  host->set("shadows.fit=cascades");
  host->set("shadows.cascade_count=4");
  host->set("shadows.map_size=512");  // four 512^2 maps: the memory of one 1024^2
  const double cascades = misclassified(*host, truth);
  std::printf("misclassified %%: scene fit %.4f, view fit %.4f, 4 cascades of 512^2 %.4f\n", scene, view, cascades);
  EXPECT_GT(scene, 0.05);  // the stair steps are there to remove
  EXPECT_LE(view, 0.75 * scene);
  EXPECT_LE(cascades, 0.5 * scene);
  EXPECT_LT(cascades, view);
  EXPECT_EQ(gl::drainErrors(), "");
}

TEST(ShadowMaps, EveryVisiblePixelLandsInACascade) {
  auto host = test::labHost("shadows", "learnopengl", {"shadows.view=cascades"});
  for (const char* fit : {"cascades", "depth-range"})
    for (const char* cam :
         {"", "yaw=35,pitch=8,distance=4,near=0.1,far=100", "yaw=-120,pitch=60,distance=20,near=0.1,far=100",
          "yaw=10,pitch=2,distance=1.5,near=0.1,far=100"}) {
      host->set(std::string("shadows.fit=") + fit);
      if (*cam) ASSERT_EQ(host->camera().parse(cam), "");
      for (int count : {2, 3, 4}) {
        host->set("shadows.cascade_count=" + std::to_string(count));
        ImageF img = drawn(*host, {320, 240});
        if (std::string(fit) == "depth-range") {  // the second frame splits the range the first one drew
          img = drawn(*host, {320, 240});
          EXPECT_TRUE(shadowsOf(*host).drawnRange()) << cam;
        }
        int gaps = 0, covered = 0;
        for (int y = 0; y < img.size.y; ++y)
          for (int x = 0; x < img.size.x; ++x) {
            const float* p = img.at(x, y);
            if (p[3] < 0.5f) continue;  // background
            ++covered;
            gaps += p[0] > 0.9f && p[1] < 0.1f && p[2] > 0.9f;  // magenta: outside its cascade's map
          }
        EXPECT_GT(covered, 1000) << cam;
        EXPECT_EQ(gaps, 0) << cam << " with " << count << " cascades, fit " << fit;
        EXPECT_EQ(int(shadowsOf(*host).cascades().size()), count);
      }
    }
}

// fit = depth-range splits the cascades over the nearest and farthest view depth the camera drew
// the frame before: the GPU's reduction agrees with the depth buffer read back and reduced here,
// and a frame from another camera does not use it.
TEST(ShadowMaps, TheDepthRangeFitSplitsWhatTheCameraDrew) {
  auto host = test::labHost("shadows", "learnopengl", {"shadows.fit=depth-range", "shadows.map_size=512"});
  ASSERT_EQ(host->camera().parse("yaw=20,pitch=8,distance=2.2,target=2;0;1,fov=45,near=0.1,far=100"), "");
  const glm::ivec2 size(320, 240);
  const gl::RenderTarget target = gl::RenderTarget::create(size);
  host->drawInto(target, host->camera(), 0.0f);
  EXPECT_FALSE(shadowsOf(*host).drawnRange()) << "nothing was drawn before the first frame";
  std::vector<float> depth(size_t(size.x * size.y));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, target.fbo());
  glReadPixels(0, 0, size.x, size.y, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
  const float n = host->camera().nearPlane, f = host->camera().farPlane;
  glm::vec2 expected(INFINITY, -INFINITY);
  for (float z : depth)
    if (z < 1.0f) {
      const float d = n * f / (f - z * (f - n));
      expected = {std::min(expected.x, d), std::max(expected.y, d)};
    }
  ASSERT_LT(expected.x, expected.y);
  host->drawInto(target, host->camera(), 0.0f);
  const auto range = shadowsOf(*host).drawnRange();
  ASSERT_TRUE(range);
  EXPECT_NEAR(range->x, expected.x, 1e-4f * expected.x);
  EXPECT_NEAR(range->y, expected.y, 1e-4f * expected.y);
  // The frustum's own range holds it; this camera sees the far floor past the cube only in part.
  EXPECT_LT(range->y, 35.0f);
  host->camera().target.x += 0.5f;
  host->drawInto(target, host->camera(), 0.0f);
  EXPECT_FALSE(shadowsOf(*host).drawnRange()) << "a range drawn from another camera was used";
}

TEST(ShadowMaps, SnappedMapsStayStillUnderASubTexelCameraMove) {
  for (bool snap : {true, false}) {
    auto host = test::labHost(
        "shadows", "learnopengl",
        {"shadows.fit=cascades", "shadows.map_size=512", std::string("shadows.snap_texels=") + (snap ? "on" : "off")});
    host->renderFrame({200, 150});
    const auto& lab = shadowsOf(*host);
    const float texel = lab.cascades()[0].light.texelWorld(0, 512);
    const std::vector<float> before = depthLayer(lab.keyMap(), 0);
    host->camera().target.x += 0.2f * texel;  // a fifth of the nearest cascade's texel
    host->renderFrame({200, 150});
    const std::vector<float> after = depthLayer(lab.keyMap(), 0);
    // Still: the same texels, or the same ones a whole texel over (the centre rounded the other
    // way), which keeps the texel grid where it was in the world, so edges do not crawl. "The
    // same" within a few 24-bit steps: a shifted projection rounds the last bit differently. A
    // fifth of a texel on this floor moves depth by ~3e-5, and silhouettes by whole texels.
    size_t fewest = before.size();
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        size_t changed = 0;
        for (int y = 1; y < 511; ++y)
          for (int x = 1; x < 511; ++x)
            changed += std::abs(before[size_t(y * 512 + x)] - after[size_t((y + dy) * 512 + x + dx)]) > 1e-6f;
        fewest = std::min(fewest, changed);
      }
    if (snap)
      EXPECT_LT(fewest, before.size() / 1000) << "a snapped map changed under a sub-texel move";
    else
      EXPECT_GT(fewest, before.size() / 10) << "without snapping the map follows the camera (and shimmers)";
  }
}

// The blocker search compares each tap with the receiver's plane at that tap: on a sloped
// receiver the surface itself must not count as a blocker, or the penumbra shrinks.
TEST(ShadowMaps, PcssPenumbraOnASlopeIsNotNarrowerThanOnTheFlat) {
  // A plate 1 unit above a receiver, the plate's edge over the origin; the light straight above.
  // The sloped receiver turns about the z axis through the origin, so under the edge the
  // blocker-receiver distance is the same as on the flat.
  auto writeScene = [](const std::string& path, float slopeDeg) {
    std::ofstream f(path);
    const float c = std::cos(glm::radians(slopeDeg)), s = std::sin(glm::radians(slopeDeg));
    for (auto [x, z] : {std::pair{-4.0f, -4.0f}, {4.0f, -4.0f}, {4.0f, 4.0f}, {-4.0f, 4.0f}})
      f << "v " << x * c << " " << x * s << " " << z << "\n";
    for (auto [x, z] : {std::pair{-3.0f, -3.0f}, {0.0f, -3.0f}, {0.0f, 3.0f}, {-3.0f, 3.0f}})
      f << "v " << x << " 1 " << z << "\n";
    // Two specks far out give both scenes the same bounds, hence the same map and texel size.
    f << "v -6 -3 -6\nv -5.99 -3 -6\nv -6 -3 -5.99\nv 6 3 6\nv 5.99 3 6\nv 6 3 5.99\n";
    f << "f 1 4 3\nf 1 3 2\nf 5 8 7\nf 5 7 6\nf 9 10 11\nf 12 13 14\n";
  };
  double penumbra[2] = {0, 0};
  for (int sloped = 0; sloped < 2; ++sloped) {
    const std::string path = test::testOutput(sloped ? "pcss_slope.obj" : "pcss_flat.obj").string();
    writeScene(path, sloped ? 35.0f : 0.0f);
    auto host = test::labHost(
        "shadows", path.c_str(),
        {"shadows.filter=pcss", "shadows.light_elevation=90", "shadows.light_radius=0.5", "shadows.blocker_samples=32",
         "shadows.pcss_samples=32", "shadows.view=pcss-penumbra", "shadows.map_size=1024"});
    // From the open side, so the floor under the plate's edge (the origin) is the image centre.
    host->renderFrame({64, 64});  // builds the scene (and frames the camera) first
    ASSERT_EQ(host->camera().parse("yaw=90,pitch=40,distance=5,target=0;0;0,near=0.05,far=50"), "");
    const ImageF img = drawn(*host, {200, 200});
    writePng(test::testOutput(sloped ? "pcss_slope_penumbra.png" : "pcss_flat_penumbra.png").string(), img);
    // The penumbra width (red: texels / 32) around the image centre, under the plate's edge.
    double sum = 0;
    int n = 0;
    for (int y = 98; y < 103; ++y)
      for (int x = 90; x < 110; ++x) {
        const float r = img.at(x, y)[0];
        sum += std::pow(r, 2.2f) * 32.0;  // the view is sRGB-encoded
        ++n;
      }
    penumbra[sloped] = sum / n;
  }
  std::printf("PCSS penumbra under the plate's edge: flat %.2f texels, sloped 35 deg %.2f texels\n", penumbra[0],
              penumbra[1]);
  EXPECT_GT(penumbra[0], 2.0);
  EXPECT_GE(penumbra[1], 0.9 * penumbra[0]);
}

TEST(ShadowMaps, ShadersHoldTheDiskOfTheirOwnSampleCount) {
  for (const char* filter : {"poisson", "pcss"})
    for (int index = 0; index < 4; ++index) {
      const std::string count = std::to_string(8 << index);
      auto host = test::labHost("shadows", nullptr,
                                {std::string("shadows.filter=") + filter, "shadows.poisson_samples=" + count,
                                 "shadows.pcss_samples=" + count, "shadows.blocker_samples=" + count});
      host->renderFrame({64, 36});
      GLint program = 0;
      for (auto& p : host->lab().activePrograms())
        if (p->spec().name.rfind("shadows/lit", 0) == 0) {
          p->use();
          glGetIntegerv(GL_CURRENT_PROGRAM, &program);
        }
      ASSERT_NE(program, 0);
      const auto& disk = ShadowsLab::disk(8 << index);
      for (const char* name : {"u_filterDisk", "u_blockerDisk"}) {
        for (int k = 0; k < (8 << index); ++k) {
          const GLint loc =
              glGetUniformLocation(GLuint(program), (std::string(name) + "[" + std::to_string(k) + "]").c_str());
          if (loc < 0) continue;  // not used by this filter
          float v[2];
          glGetUniformfv(GLuint(program), loc, v);
          EXPECT_EQ(glm::vec2(v[0], v[1]), disk[size_t(k)]) << filter << " " << name << "[" << k << "] of " << count;
        }
      }
    }
}

// Filtered maps blur the shadow uniformly: softer edges everywhere (so VSM, leaking light near
// contacts, need not beat a hard shadow against the area light), and for ESM and EVSM, whose
// exponential warps keep contacts dark, closer to the area light's truth than a hard shadow.
TEST(ShadowMaps, FilteredMapsSoftenAndEsmAndEvsmImitateTheAreaLight) {
  auto host = test::labHost("shadows", nullptr, {"shadows.light_radius=0.15", "shadows.filter=hard"});
  const ImageF truth = host->renderReference({240, 135});
  auto penumbraPct = [](const ImageF& img) {
    int soft = 0, valid = 0;
    for (size_t i = 0; i < img.rgba.size(); i += 4) {
      if (img.rgba[i + 3] < 0.5f) continue;
      ++valid;
      soft += img.rgba[i] > 0.05f && img.rgba[i] < 0.95f;
    }
    return 100.0 * soft / std::max(valid, 1);
  };
  const ImageF hardImage = host->renderMeasured({240, 135});
  const double hard = test::metric(host->lab().judge()->metrics(hardImage, truth), "visibility_rmse_area");
  for (const char* f : {"vsm", "esm", "evsm"}) {
    host->set(std::string("shadows.filter=") + f);
    host->set("shadows.blur_radius=4");
    const ImageF img = host->renderMeasured({240, 135});
    ASSERT_EQ(countNonFinite(img), 0u) << f;
    const double area = test::metric(host->lab().judge()->metrics(img, truth), "visibility_rmse_area");
    std::printf("%s: visibility_rmse_area %.4f (hard %.4f), penumbra pixels %.2f%% (hard %.2f%%)\n", f, area, hard,
                penumbraPct(img), penumbraPct(hardImage));
    EXPECT_GT(penumbraPct(img), 2.0 * penumbraPct(hardImage) + 1.0) << f;
    if (std::string(f) != "vsm") EXPECT_LT(area, hard) << f;
  }
  EXPECT_EQ(gl::drainErrors(), "");
}

// A mipmapped moment map read with one level per 2x2 quad (anisotropic textureGrad on llvmpipe) or in a
// branch only some pixels of a quad take reads the wrong level where neighbouring pixels use
// different cascades: isolated dark dots along every split and every silhouette.
TEST(ShadowMaps, FilteredCascadesLeaveNoDotsOnALitFloor) {
  auto host = test::labHost("shadows", "learnopengl", {"shadows.fit=cascades", "shadows.moment_mips=on"});
  const glm::ivec2 size(800, 600);
  const ImageF truth = host->renderReference(size);
  for (const char* f : {"vsm", "esm", "evsm"}) {
    host->set(std::string("shadows.filter=") + f);
    const ImageF img = drawn(*host, size);  // the shaded frame, as the student sees it
    int dots = 0;
    for (int y = 2; y < size.y - 2; ++y)
      for (int x = 0; x < size.x; ++x) {
        auto lum = [&](int dy) { return img.at(x, y + dy)[1]; };
        if (truth.at(x, y)[3] < 0.5f || truth.at(x, y)[0] < 0.99f) continue;  // truly lit only
        dots += lum(0) < 0.85f * std::min(lum(-2), lum(2));                   // darker than the floor above and below
      }
    std::printf("%s: %d pixels darker than the lit floor two rows above and below\n", f, dots);
    EXPECT_LE(dots, 20) << f << ": thin dark lines on truly lit surfaces";  // ~250 with per-quad levels
  }
}

TEST(ShadowMaps, CubeMapsFilterSeamlessly) {
  auto host = test::labHost("shadows", nullptr, {"shadows.light_type=point", "shadows.filter=hardware-pcf"});
  host->renderFrame({64, 36});
  EXPECT_TRUE(glIsEnabled(GL_TEXTURE_CUBE_MAP_SEAMLESS));
}

// pcf-bilinear writes out what the hardware-pcf sampler does (one depth for the four texels, so
// without the receiver plane): the two visibility images agree.
TEST(ShadowMaps, BilinearPcfInTheShaderMatchesTheSampler) {
  auto host = test::labHost("shadows", nullptr,
                            {"shadows.filter=hardware-pcf", "shadows.view=visibility", "shadows.receiver_plane=off"});
  host->renderFrame({320, 180});
  const ImageF sampler = host->readImage();
  ASSERT_EQ(host->set("shadows.filter=pcf-bilinear"), "");
  host->renderFrame({320, 180});
  const ImageError e = compareImages(host->readImage(), sampler);
  std::printf("pcf-bilinear against hardware-pcf: rmse %.5f, max %.4f\n", e.rmse, e.maxError);
  EXPECT_LT(e.rmse, 0.01);
}

// A map over the lab's memory budget is drawn smaller, and the lab says why: one 8192^2 map of
// EVSM moments with mips and the blur's scratch is 2.6 GiB, which a software renderer would take
// from the machine's memory.
TEST(ShadowMaps, AMapOverTheBudgetIsDrawnSmallerAndSaysSo) {
  auto host =
      test::labHost("shadows", "shadow-test", {"shadows.fit=scene", "shadows.filter=evsm", "shadows.map_size=8192"});
  host->renderFrame({160, 90});
  EXPECT_EQ(shadowsOf(*host).keyMap().size(), 4096);
  bool said = false;
  for (const std::string& w : host->warnings()) said |= w.find("over the lab's 2 GiB budget") != std::string::npos;
  EXPECT_TRUE(said);
  EXPECT_GT(ShadowMap::bytesOf({false, 8192, 1, GL_DEPTH_COMPONENT24, GL_RGBA32F, true}), ShadowMap::kBudgetBytes);
  EXPECT_LT(ShadowMap::bytesOf({false, 8192, 4, GL_DEPTH_COMPONENT24, 0, false}),
            ShadowMap::kBudgetBytes);  // depth alone fits
  EXPECT_EQ(gl::drainErrors(), "");
}

// The budget is the lab's, not each map's: a casting fill light's map gets what the key light's
// leaves (two 8192^2 VSM maps, 1.4 GiB each, were 2.9 GB between them).
TEST(ShadowMaps, TheKeyAndFillMapsShareTheBudget) {
  auto host = test::labHost("shadows", "shadow-test",
                            {"shadows.light_type=spot", "shadows.filter=vsm", "shadows.map_size=8192",
                             "shadows.fill_light=on", "shadows.fill_casts=on"});
  host->renderFrame({160, 90});
  const ShadowsLab& lab = shadowsOf(*host);
  EXPECT_EQ(lab.keyMap().size(), 8192) << "the key light's map fits the budget alone";
  EXPECT_LT(lab.fillMap().size(), 8192);
  EXPECT_LE(lab.keyMap().bytes() + lab.fillMap().bytes(), ShadowMap::kBudgetBytes);
  bool said = false;
  for (const std::string& w : host->warnings())
    said |= w.find("fill shadow map") != std::string::npos && w.find("the key light's maps take") != std::string::npos;
  EXPECT_TRUE(said) << "the fill light's smaller map is named, with what the key light's take";
  host->set("shadows.fill_casts=off");
  host->renderFrame({160, 90});
  host->set("shadows.fill_casts=on");
  host->set("shadows.map_size=2048");
  host->renderFrame({160, 90});
  EXPECT_EQ(lab.fillMap().size(), 2048) << "within the budget again, the fill light's map is drawn as asked";
  EXPECT_EQ(gl::drainErrors(), "");
}

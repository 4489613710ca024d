// The shading lab measured against its reference (per-fragment Phong on the finest mesh).
#include <gtest/gtest.h>

#include "gl_test.h"

using namespace shadelab;

static double errorOf(LabHost& host, const std::vector<std::string>& sets, const ImageF& reference) {
  for (auto& s : sets) EXPECT_EQ(host.set(s), "");
  host.renderFrame(reference.size);
  // Surface error: the silhouette of a coarse mesh is the same for every mode and would hide them.
  return compareImages(host.readImage(), reference).coveredRmse;
}

TEST(ShadingReference, ErrorOrdersByFrequencyAndFallsWithTessellation) {
  LabHost host(test::builtinShaders());
  ASSERT_EQ(host.selectScene("sphere"), "");
  const ImageF ref = host.renderReference({192, 192});
  ASSERT_EQ(countNonFinite(ref), 0u);
  const double flat = errorOf(host, {"shading.mode=flat", "shading.tessellation=16"}, ref);
  const double gouraud = errorOf(host, {"shading.mode=gouraud"}, ref);
  const double phong = errorOf(host, {"shading.mode=phong"}, ref);
  EXPECT_GT(flat, gouraud);
  EXPECT_GT(gouraud, phong);
  const double phongFine = errorOf(host, {"shading.tessellation=128"}, ref);
  EXPECT_LT(phongFine, phong);
  EXPECT_LT(phongFine, 0.005);  // only the tessellation differs from the reference now
  const double flatFine = errorOf(host, {"shading.mode=flat", "shading.tessellation=128"}, ref);
  EXPECT_LT(flatFine, flat);
}

TEST(ShadingReference, AffineUvsAreWrongOnlyUnderPerspective) {
  LabHost host(test::builtinShaders());
  ASSERT_EQ(host.selectScene("checker-plane"), "");
  ASSERT_EQ(host.set("shading.mode=phong"), "");
  host.renderFrame({192, 108});
  const ImageF correct = host.readImage();
  ASSERT_EQ(host.set("shading.uv_interpolation=affine"), "");
  host.renderFrame({192, 108});
  EXPECT_GT(compareImages(host.readImage(), correct).badPixelPct, 5.0);  // bent checker lines
  // Seen straight down, w is constant across the floor: affine equals perspective-correct.
  ASSERT_EQ(host.camera().parse("pitch=89.9,yaw=0"), "");
  host.set("shading.uv_interpolation=perspective");
  host.renderFrame({192, 108});
  const ImageF top = host.readImage();
  host.set("shading.uv_interpolation=affine");
  host.renderFrame({192, 108});
  EXPECT_LT(compareImages(host.readImage(), top).badPixelPct, 0.5);
}

// Jittered accumulation converges: an analytic image (a disk's hard edge and a fine stripe
// pattern) point-sampled at jittered offsets approaches its exact box-filtered value.
#include <gtest/gtest.h>

#include <cmath>

#include "app/measure/accumulator.h"

using namespace shadelab;

namespace {

// "Renders" a 64 x 64 frame of the scene, every pixel sampled at its centre + offset.
ImageF renderShifted(glm::vec2 offset) {
  ImageF img;
  img.size = {64, 64};
  img.rgba.resize(64 * 64 * 4);
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      const glm::vec2 p = glm::vec2(x + 0.5f, y + 0.5f) + offset;
      const bool inDisk = glm::length(p - glm::vec2(32.0f)) < 20.3f;
      const bool stripe = std::fmod(p.x * 0.37f + p.y * 0.11f, 1.0f) < 0.5f;
      float* px = img.at(x, y);
      px[0] = px[1] = px[2] = inDisk ? (stripe ? 0.9f : 0.2f) : 0.05f;
      px[3] = inDisk ? 1.0f : 0.0f;
    }
  return img;
}

ImageF accumulate(int grid, PixelFilter filter, uint32_t seed) {
  ImageAccumulator acc(true);
  for (auto& s : jitterSamples(grid, filter, seed)) acc.add(renderShifted(s.offset), s.weight);
  return acc.mean();
}

}  // namespace

TEST(Accumulation, SamplesAreStratifiedInsideTheFilterSupport) {
  const auto box = jitterSamples(4, PixelFilter::Box);
  ASSERT_EQ(box.size(), 16u);
  int perQuadrant[4] = {};
  for (auto& s : box) {
    EXPECT_LE(std::abs(s.offset.x), 0.5f);
    EXPECT_LE(std::abs(s.offset.y), 0.5f);
    EXPECT_EQ(s.weight, 1.0f);
    ++perQuadrant[(s.offset.x > 0) + 2 * (s.offset.y > 0)];
  }
  for (int q : perQuadrant) EXPECT_EQ(q, 4) << "a 4 x 4 stratification puts four samples in each quadrant";
  for (auto& s : jitterSamples(4, PixelFilter::Gaussian)) EXPECT_LE(std::abs(s.offset.x), 1.5f);
  EXPECT_EQ(jitterSamples(1, PixelFilter::Box)[0].offset, glm::vec2(0.0f)) << "one sample is a plain frame";
}

TEST(Accumulation, SixteenAndThirtyTwoSquaredDifferByLessThanStated) {
  // The stated bound: 16 x 16 samples are within RMSE 0.004 (about one 8-bit step) of 32 x 32.
  const ImageF s16 = accumulate(16, PixelFilter::Box, 1), s32 = accumulate(32, PixelFilter::Box, 2);
  const double converged = compareImages(s16, s32).rmse;
  EXPECT_LT(converged, 0.004);
  const double single = compareImages(accumulate(1, PixelFilter::Box, 1), s32).rmse;
  EXPECT_GT(single, 10 * converged) << "one sample per pixel aliases; accumulation must remove most of it";
  const double s4 = compareImages(accumulate(4, PixelFilter::Box, 3), s32).rmse;
  EXPECT_GT(s4, converged) << "more samples, closer";
}

TEST(Accumulation, AveragesInLinearLightAndKeepsCoverage) {
  ImageF black, white;
  black.size = white.size = {1, 1};
  black.rgba = {0, 0, 0, 1};
  white.rgba = {1, 1, 1, 0};
  ImageAccumulator acc(true);
  acc.add(black, 1.0f);
  acc.add(white, 1.0f);
  const ImageF m = acc.mean();
  EXPECT_NEAR(m.rgba[0], linearToSrgb(0.5f), 1e-6f) << "half black, half white is 0.735 encoded, not 0.5";
  EXPECT_NEAR(m.rgba[3], 0.5f, 1e-6f);
  ImageAccumulator raw(false);
  raw.add(black, 1.0f);
  raw.add(white, 3.0f);
  EXPECT_NEAR(raw.mean().rgba[0], 0.75f, 1e-6f);
}

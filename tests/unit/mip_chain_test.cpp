// Mip chains made on the CPU: OpenGL's sizes for any texture, the mean kept exactly by the box
// filter (odd sizes included), constants kept by both filters, and the Kaiser kernel's shape.
#include <gtest/gtest.h>

#include <random>

#include "app/scene/mip_chain.h"

using namespace shadelab;

namespace {

LinearImage noise(glm::ivec2 size, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  LinearImage img{size, std::vector<glm::vec4>(size_t(size.x) * size_t(size.y))};
  for (auto& t : img.texels) t = {u(rng), u(rng), u(rng), 1.0f};
  return img;
}

glm::dvec4 mean(const LinearImage& img) {
  glm::dvec4 sum(0.0);
  for (auto& t : img.texels) sum += glm::dvec4(t);
  return sum / double(img.texels.size());
}

}  // namespace

TEST(MipChain, SizesFollowOpenGLForNonPowerOfTwoTextures) {
  const auto chain = buildMipChain(noise({300, 200}, 1), MipDownsampler::Box);
  const std::vector<glm::ivec2> expected = {{300, 200}, {150, 100}, {75, 50}, {37, 25}, {18, 12},
                                            {9, 6},     {4, 3},     {2, 1},   {1, 1}};
  ASSERT_EQ(chain.size(), expected.size());
  EXPECT_EQ(mipLevelCount({300, 200}), 9);
  for (size_t l = 0; l < chain.size(); ++l) {
    EXPECT_EQ(chain[l].size, expected[l]) << "level " << l;
    EXPECT_EQ(mipLevelSize({300, 200}, int(l)), expected[l]);
  }
  EXPECT_EQ(mipLevelCount({1, 1}), 1);
  EXPECT_EQ(mipLevelCount({1, 7}), 3);
  EXPECT_EQ(buildMipChain(noise({1, 1}, 2), MipDownsampler::Kaiser).size(), 1u);
}

TEST(MipChain, TheBoxFilterKeepsTheMeanOfEveryLevelForOddSizes) {
  for (glm::ivec2 size : {glm::ivec2(300, 200), glm::ivec2(37, 25), glm::ivec2(5, 3), glm::ivec2(64, 64)}) {
    const auto chain = buildMipChain(noise(size, 3), MipDownsampler::Box);
    const glm::dvec4 m0 = mean(chain[0]);
    for (size_t l = 1; l < chain.size(); ++l)
      for (int c = 0; c < 4; ++c)
        EXPECT_NEAR(mean(chain[l])[c], m0[c], 2e-6) << size.x << "x" << size.y << " level " << l;
  }
}

TEST(MipChain, AnOddRowOfThreeBecomesTheirMean) {
  LinearImage img{{3, 1}, {glm::vec4(0.0f), glm::vec4(0.3f), glm::vec4(0.9f)}};
  const LinearImage next = downsampleLevel(img, MipDownsampler::Box);
  ASSERT_EQ(next.size, glm::ivec2(1, 1));
  EXPECT_NEAR(next.texels[0].r, 0.4f, 1e-6f);
  // Five texels to two: each covers 2.5, the middle texel split between them.
  LinearImage five{{5, 1}, {glm::vec4(1.0f), glm::vec4(1.0f), glm::vec4(0.0f), glm::vec4(0.0f), glm::vec4(0.0f)}};
  const LinearImage two = downsampleLevel(five, MipDownsampler::Box);
  ASSERT_EQ(two.size, glm::ivec2(2, 1));
  EXPECT_NEAR(two.texels[0].r, 2.0f / 2.5f, 1e-6f);
  EXPECT_NEAR(two.texels[1].r, 0.0f, 1e-6f);
}

TEST(MipChain, BothFiltersKeepAConstant) {
  LinearImage grey{{96, 40}, std::vector<glm::vec4>(96 * 40, glm::vec4(0.25f, 0.5f, 0.75f, 1.0f))};
  for (MipDownsampler how : {MipDownsampler::Box, MipDownsampler::Kaiser})
    for (const LinearImage& level : buildMipChain(grey, how))
      for (const glm::vec4& t : level.texels) {
        EXPECT_NEAR(t.r, 0.25f, 1e-5f);
        EXPECT_NEAR(t.b, 0.75f, 1e-5f);
      }
}

TEST(MipChain, KaiserKeepsMoreOfAFrequencyBelowNyquistThanTheBox) {
  // Stripes of period 6 texels: 3 texels after one level, still representable. The box filter
  // attenuates them more than the windowed sinc does.
  LinearImage stripes{{96, 4}, std::vector<glm::vec4>(96 * 4)};
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 96; ++x) stripes.at(x, y) = glm::vec4(0.5f + 0.5f * std::cos(2.0f * float(M_PI) * x / 6.0f));
  auto amplitude = [](const LinearImage& img) {
    float lo = 1.0f, hi = 0.0f;
    for (auto& t : img.texels) {
      lo = std::min(lo, t.r);
      hi = std::max(hi, t.r);
    }
    return hi - lo;
  };
  const float box = amplitude(downsampleLevel(stripes, MipDownsampler::Box));
  const float kaiser = amplitude(downsampleLevel(stripes, MipDownsampler::Kaiser));
  EXPECT_GT(kaiser, box * 1.05f) << "box " << box << ", kaiser " << kaiser;
}

TEST(MipChain, TheKaiserKernelIsAWindowedSinc) {
  EXPECT_DOUBLE_EQ(kaiserSinc(0.0), 1.0);
  EXPECT_NEAR(kaiserSinc(1.0), 0.0, 1e-12);  // the sinc's zeros survive the window
  EXPECT_NEAR(kaiserSinc(2.0), 0.0, 1e-12);
  EXPECT_EQ(kaiserSinc(3.0), 0.0);  // nothing beyond the width
  EXPECT_LT(kaiserSinc(1.5), 0.0);  // the first negative lobe
  EXPECT_DOUBLE_EQ(kaiserSinc(0.7), kaiserSinc(-0.7));
  EXPECT_NEAR(besselI0(0.0), 1.0, 1e-15);
  EXPECT_NEAR(besselI0(4.0), 11.301921952136330, 1e-10);  // I0(4), tabulated
}

TEST(MipChain, SrgbBytesSurviveTheRoundTripThroughLinearLight) {
  std::vector<uint8_t> rgba(256 * 4);
  for (int i = 0; i < 256; ++i)
    rgba[size_t(i) * 4] = rgba[size_t(i) * 4 + 1] = rgba[size_t(i) * 4 + 2] = rgba[size_t(i) * 4 + 3] = uint8_t(i);
  EXPECT_EQ(encodeSrgb8(decodeSrgb8({256, 1}, rgba)), rgba);
}

// Mip chains made on the CPU: for the scenes' textures (the box filter, as a driver's
// glGenerateMipmap makes it, without the blit a software driver compiles anew in every process),
// and in the filtering lab, where how a level is made is something a student can choose and
// compare: a box filter (what most drivers do) or a Kaiser-windowed sinc (what texture tools do,
// e.g. NVIDIA Texture Tools' default, width 3, alpha 4). Both work in linear light: averaging
// sRGB-encoded values darkens every level a little (the mean of the codes is not the code of the
// mean), which the chain's contrast column makes visible.
//
// Sizes follow OpenGL for any texture, power of two or not: level k is max(1, floor(w / 2^k)),
// down to 1 x 1. A destination texel of a level whose source is s times larger covers exactly s
// source texels (s = w / w' is 2, or a little more for odd sizes), so the box filter integrates
// over that interval, fractional texels at its ends included: the mean of every level is the
// mean of the image, for NPOT sizes as well.
#pragma once
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace shadelab {

enum class MipDownsampler { Box, Kaiser };

struct LinearImage {
  glm::ivec2 size{0};
  std::vector<glm::vec4> texels;  // linear light (alpha linear too), row by row
  glm::vec4& at(int x, int y) { return texels[size_t(y) * size_t(size.x) + size_t(x)]; }
  const glm::vec4& at(int x, int y) const { return texels[size_t(y) * size_t(size.x) + size_t(x)]; }
};

int mipLevelCount(glm::ivec2 size);                   // 1 + floor(log2(max(w, h)))
glm::ivec2 mipLevelSize(glm::ivec2 size, int level);  // max(1, floor(size / 2^level))

// The next level of `image`. `wrap`: the texture repeats, so kernels read across its edges;
// otherwise they are clamped to it.
LinearImage downsampleLevel(const LinearImage& image, MipDownsampler how, bool wrap = true);
// Every level from `level0` down to 1 x 1, level 0 first.
std::vector<LinearImage> buildMipChain(LinearImage level0, MipDownsampler how, bool wrap = true);

// RGBA8 sRGB (alpha linear) to linear float and back (rounded to nearest, clamped).
LinearImage decodeSrgb8(glm::ivec2 size, const std::vector<uint8_t>& rgba);
std::vector<uint8_t> encodeSrgb8(const LinearImage& image);
// 8-bit data that is linear already (a normal map, a height map), `channels` (1 to 4) per texel:
// the channels missing from a texel read as 0 (alpha 1); encoding keeps the first `channels`.
LinearImage decodeLinear8(glm::ivec2 size, const std::vector<uint8_t>& data, int channels);
std::vector<uint8_t> encodeLinear8(const LinearImage& image, int channels);

// The Kaiser window's zeroth-order modified Bessel function, and the kernel's weight at `t`
// destination texels from the centre (sinc times the window, zero beyond `width`).
double besselI0(double x);
double kaiserSinc(double t, double width = 3.0, double alpha = 4.0);

}  // namespace shadelab

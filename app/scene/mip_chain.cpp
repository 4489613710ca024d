#include "app/scene/mip_chain.h"

#include <algorithm>
#include <cmath>

#include "app/measure/accumulator.h"  // srgbToLinear, linearToSrgb

namespace shadelab {
namespace {

// One output texel's taps along one axis: source index and weight (summing to 1).
struct Tap {
  int index;
  float weight;
};
using Taps = std::vector<std::vector<Tap>>;

int wrapIndex(int i, int n, bool wrap) { return wrap ? ((i % n) + n) % n : std::clamp(i, 0, n - 1); }

// The taps that take a row of n texels to m = max(1, n / 2) texels.
Taps axisTaps(int n, int m, MipDownsampler how, bool wrap) {
  const double s = double(n) / double(m);  // source texels per destination texel: 2, or more for odd n
  Taps taps(static_cast<size_t>(m));
  for (int x = 0; x < m; ++x) {
    std::vector<Tap>& out = taps[size_t(x)];
    double sum = 0.0;
    if (how == MipDownsampler::Box) {
      // The destination texel covers [x s, (x + 1) s) of the source: every texel by its overlap.
      const double a = x * s, b = (x + 1) * s;
      for (int i = int(std::floor(a)); i < int(std::ceil(b)); ++i) {
        const double overlap = std::min(double(i + 1), b) - std::max(double(i), a);
        if (overlap > 1e-12) out.push_back({wrapIndex(i, n, wrap), float(overlap)});
      }
    } else {
      // Windowed sinc, cut off at the destination's Nyquist frequency: the kernel is stretched
      // by s, so it spans 3 destination texels each side.
      constexpr double kWidth = 3.0;
      const double c = (x + 0.5) * s - 0.5;  // the destination centre in source texel indices
      for (int i = int(std::ceil(c - kWidth * s)); i <= int(std::floor(c + kWidth * s)); ++i) {
        const double w = kaiserSinc((i - c) / s, kWidth);
        if (w != 0.0) out.push_back({wrapIndex(i, n, wrap), float(w)});
      }
    }
    for (const Tap& t : out) sum += t.weight;
    for (Tap& t : out) t.weight = float(t.weight / sum);
  }
  return taps;
}

}  // namespace

int mipLevelCount(glm::ivec2 size) {
  int levels = 1;
  for (int m = std::max(size.x, size.y); m > 1; m /= 2) ++levels;
  return levels;
}

glm::ivec2 mipLevelSize(glm::ivec2 size, int level) {
  return glm::max(glm::ivec2(1), glm::ivec2(size.x >> level, size.y >> level));
}

double besselI0(double x) {
  // The power series sum ((x/2)^k / k!)^2 converges fast for the arguments a window uses (< 20).
  double sum = 1.0, term = 1.0;
  for (int k = 1; k < 64 && term > 1e-16 * sum; ++k) {
    term *= (x / (2.0 * k)) * (x / (2.0 * k));
    sum += term;
  }
  return sum;
}

double kaiserSinc(double t, double width, double alpha) {
  if (std::abs(t) >= width) return 0.0;
  const double pt = M_PI * t;
  const double sinc = std::abs(t) < 1e-9 ? 1.0 : std::sin(pt) / pt;
  const double r = t / width;
  return sinc * besselI0(alpha * std::sqrt(1.0 - r * r)) / besselI0(alpha);
}

LinearImage downsampleLevel(const LinearImage& image, MipDownsampler how, bool wrap) {
  const glm::ivec2 from = image.size, to = mipLevelSize(from, 1);
  const Taps tx = axisTaps(from.x, to.x, how, wrap), ty = axisTaps(from.y, to.y, how, wrap);
  // Rows first (from.y rows of to.x texels), then columns.
  LinearImage rows{{to.x, from.y}, std::vector<glm::vec4>(size_t(to.x) * size_t(from.y))};
  for (int y = 0; y < from.y; ++y)
    for (int x = 0; x < to.x; ++x) {
      glm::vec4 sum(0.0f);
      for (const Tap& t : tx[size_t(x)]) sum += t.weight * image.at(t.index, y);
      rows.at(x, y) = sum;
    }
  LinearImage out{to, std::vector<glm::vec4>(size_t(to.x) * size_t(to.y))};
  for (int y = 0; y < to.y; ++y)
    for (int x = 0; x < to.x; ++x) {
      glm::vec4 sum(0.0f);
      for (const Tap& t : ty[size_t(y)]) sum += t.weight * rows.at(x, t.index);
      // A sinc's negative lobes overshoot at sharp edges: keep what a texture can store.
      out.at(x, y) = how == MipDownsampler::Box ? sum : glm::clamp(sum, 0.0f, 1.0f);
    }
  return out;
}

std::vector<LinearImage> buildMipChain(LinearImage level0, MipDownsampler how, bool wrap) {
  std::vector<LinearImage> chain;
  chain.reserve(size_t(mipLevelCount(level0.size)));
  chain.push_back(std::move(level0));
  while (chain.back().size != glm::ivec2(1)) chain.push_back(downsampleLevel(chain.back(), how, wrap));
  return chain;
}

LinearImage decodeSrgb8(glm::ivec2 size, const std::vector<uint8_t>& rgba) {
  float table[256];
  for (int i = 0; i < 256; ++i) table[i] = srgbToLinear(float(i) / 255.0f);
  LinearImage out{size, std::vector<glm::vec4>(size_t(size.x) * size_t(size.y))};
  for (size_t i = 0; i < out.texels.size(); ++i)
    out.texels[i] = {table[rgba[i * 4]], table[rgba[i * 4 + 1]], table[rgba[i * 4 + 2]],
                     float(rgba[i * 4 + 3]) / 255.0f};
  return out;
}

std::vector<uint8_t> encodeSrgb8(const LinearImage& image) {
  std::vector<uint8_t> out(image.texels.size() * 4);
  auto byte = [](float v) { return uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); };
  for (size_t i = 0; i < image.texels.size(); ++i) {
    const glm::vec4 c = image.texels[i];
    out[i * 4] = byte(linearToSrgb(c.r));
    out[i * 4 + 1] = byte(linearToSrgb(c.g));
    out[i * 4 + 2] = byte(linearToSrgb(c.b));
    out[i * 4 + 3] = byte(c.a);
  }
  return out;
}

LinearImage decodeLinear8(glm::ivec2 size, const std::vector<uint8_t>& data, int channels) {
  LinearImage out{size, std::vector<glm::vec4>(size_t(size.x) * size_t(size.y), glm::vec4(0, 0, 0, 1))};
  for (size_t i = 0; i < out.texels.size(); ++i)
    for (int c = 0; c < channels; ++c) out.texels[i][c] = float(data[i * size_t(channels) + size_t(c)]) / 255.0f;
  return out;
}

std::vector<uint8_t> encodeLinear8(const LinearImage& image, int channels) {
  std::vector<uint8_t> out(image.texels.size() * size_t(channels));
  for (size_t i = 0; i < image.texels.size(); ++i)
    for (int c = 0; c < channels; ++c)
      out[i * size_t(channels) + size_t(c)] = uint8_t(std::lround(std::clamp(image.texels[i][c], 0.0f, 1.0f) * 255.0f));
  return out;
}

}  // namespace shadelab

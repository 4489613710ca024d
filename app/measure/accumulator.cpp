#include "app/measure/accumulator.h"

#include <cmath>
#include <random>

namespace shadelab {

float srgbToLinear(float v) { return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f); }
float linearToSrgb(float v) { return v <= 0.0031308f ? v * 12.92f : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f; }

std::vector<JitterSample> jitterSamples(int grid, PixelFilter filter, uint32_t seed) {
  grid = std::max(grid, 1);
  std::vector<JitterSample> out;
  if (grid == 1) return {{{0.0f, 0.0f}, 1.0f}};  // one sample: the pixel centre, as a plain frame
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  const float support = filter == PixelFilter::Box ? 1.0f : 3.0f, sigma = 0.5f;
  for (int j = 0; j < grid; ++j)
    for (int i = 0; i < grid; ++i) {
      const glm::vec2 cell((float(i) + u(rng)) / float(grid), (float(j) + u(rng)) / float(grid));
      const glm::vec2 offset = (cell - 0.5f) * support;
      const float weight =
          filter == PixelFilter::Box ? 1.0f : std::exp(-glm::dot(offset, offset) / (2 * sigma * sigma));
      out.push_back({offset, weight});
    }
  return out;
}

void ImageAccumulator::add(const ImageF& frame, float weight) {
  if (frames_ == 0) {
    size_ = frame.size;
    sum_.assign(frame.rgba.size(), 0.0);
  }
  if (frame.size != size_ || !(weight > 0.0f)) return;
  for (size_t i = 0; i < frame.rgba.size(); ++i) {
    const bool colour = displayEncoded_ && i % 4 != 3;
    sum_[i] += double(weight) * (colour ? srgbToLinear(frame.rgba[i]) : frame.rgba[i]);
  }
  weight_ += weight;
  ++frames_;
}

ImageF ImageAccumulator::mean() const {
  ImageF out;
  out.size = size_;
  out.rgba.resize(sum_.size());
  const double w = weight_ > 0.0 ? 1.0 / weight_ : 0.0;
  for (size_t i = 0; i < sum_.size(); ++i) {
    const float v = float(sum_[i] * w);
    out.rgba[i] = displayEncoded_ && i % 4 != 3 ? linearToSrgb(v) : v;
  }
  return out;
}

}  // namespace shadelab

// Supersampling without a supersized target: a reference of a W x H frame is the weighted mean of
// many W x H frames whose projection is shifted by a sub-pixel offset. A 16 x 16 reference of a
// 1280 x 720 frame is 256 frames of 1280 x 720, never one of 20480 x 11520.
//
// Offsets are stratified and jittered (one random point per cell of an n x n grid over the pixel
// filter's support), so n x n samples converge like a grid without a grid's aliasing pattern.
// Display-encoded (sRGB) frames are averaged in linear light and encoded again: the mean of two
// encoded values is not the encoding of their mean.
#pragma once
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "app/measure/image.h"

namespace shadelab {

enum class PixelFilter {
  Box,       // every point of the pixel's square counts the same
  Gaussian,  // sigma 0.5 px over a 3 x 3 px support: softer, less ringing at edges
  Count,
};

struct JitterSample {
  glm::vec2 offset{0.0f};  // pixels, from the pixel's centre
  float weight = 1.0f;
};

// grid x grid samples over the filter's support, in a fixed order for a given seed.
std::vector<JitterSample> jitterSamples(int grid, PixelFilter filter, uint32_t seed = 1);

class ImageAccumulator {
 public:
  explicit ImageAccumulator(bool displayEncoded) : displayEncoded_(displayEncoded) {}
  void add(const ImageF& frame, float weight);
  int frames() const { return frames_; }
  ImageF mean() const;  // alpha (coverage) is averaged too: a half-covered edge pixel has 0.5

 private:
  bool displayEncoded_;
  glm::ivec2 size_{0};
  std::vector<double> sum_;
  double weight_ = 0.0;
  int frames_ = 0;
};

float srgbToLinear(float v);
float linearToSrgb(float v);

}  // namespace shadelab

// Float RGBA images (rows top-down) and the error metrics every lab reports against its reference.
#pragma once
#include <string>
#include <vector>

#include <glm/vec2.hpp>

namespace shadelab {

struct ImageF {
  glm::ivec2 size{0};
  std::vector<float> rgba;  // 4 floats per pixel
  float* at(int x, int y) { return &rgba[(size_t(y) * size.x + x) * 4]; }
  const float* at(int x, int y) const { return &rgba[(size_t(y) * size.x + x) * 4]; }
};

struct ImageError {
  double rmse = 0.0;      // over RGB of all pixels, values clamped to [0,1] (display-encoded)
  double maxError = 0.0;  // largest per-channel absolute difference
  double meanError = 0.0;
  double badPixelPct = 0.0;  // pixels whose largest channel difference exceeds the threshold
  // RMSE over the pixels both images cover (alpha > 0.5): the error *inside* surfaces, without
  // the silhouette differences that dominate `rmse` when geometry is coarse. Labs clear to alpha 0.
  double coveredRmse = 0.0;
  double coveredPct = 0.0;  // share of pixels in that set
};

// Both images must have the same size.
ImageError compareImages(const ImageF& a, const ImageF& b, double badThreshold = 0.1);
// RMSE (RGB, clamped to [0,1]) over the pixels either image covers: where both draw the same
// surface, the colours' difference; where one draws and the other leaves the background, that
// difference too, unless the pixel touches (8-neighbourhood) what the other covers: a silhouette
// that moved by a pixel is not counted. Unlike `coveredRmse`, a frame that draws less than the
// other (geometry flung away, a surface discarded) cannot score 0. Same size, or 1.
double drawnRmse(const ImageF& a, const ImageF& b);
// Count of NaN or Inf values (any channel).
size_t countNonFinite(const ImageF& image);
// Box filter by an integer factor (supersampled reference -> output size).
ImageF downsample(const ImageF& image, int factor);
// |a-b| amplified (1 where either is not finite), for golden-image failure reports and the
// grader's pictures. The values as drawn, not clamped for display: a visibility of 2 beside the
// solution's 1 shows, though both look white.
ImageF diffImage(const ImageF& a, const ImageF& b, float gain = 4.0f);

// PNG output (RGB8, values clamped). Writes to a temporary name and renames, so a reader never
// sees half a file. Returns "" or an error naming the file.
std::string writePng(const std::string& path, const ImageF& image);
// PNG/JPEG input to float RGBA in [0,1]. Returns "" or an error naming the file.
std::string readImage(const std::string& path, ImageF& image);

}  // namespace shadelab

#include "app/measure/image.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include <stb_image.h>
#include <stb_image_write.h>

#include "app/util/output_files.h"

namespace shadelab {

static float clamp01(float v) { return std::isfinite(v) ? std::clamp(v, 0.0f, 1.0f) : 1.0f; }

ImageError compareImages(const ImageF& a, const ImageF& b, double badThreshold) {
  ImageError e;
  if (a.size != b.size || a.rgba.empty()) return {1.0, 1.0, 1.0, 100.0, 1.0, 0.0};
  double sumSq = 0.0, sum = 0.0, coveredSq = 0.0;
  size_t bad = 0, covered = 0;
  const size_t pixels = size_t(a.size.x) * a.size.y;
  for (size_t i = 0; i < pixels; ++i) {
    double worst = 0.0, pixelSq = 0.0;
    for (int c = 0; c < 3; ++c) {
      const double d = std::abs(double(clamp01(a.rgba[i * 4 + c])) - clamp01(b.rgba[i * 4 + c]));
      pixelSq += d * d;
      sum += d;
      worst = std::max(worst, d);
    }
    sumSq += pixelSq;
    if (a.rgba[i * 4 + 3] > 0.5f && b.rgba[i * 4 + 3] > 0.5f) {
      coveredSq += pixelSq;
      ++covered;
    }
    e.maxError = std::max(e.maxError, worst);
    bad += worst > badThreshold;
  }
  e.rmse = std::sqrt(sumSq / double(pixels * 3));
  e.meanError = sum / double(pixels * 3);
  e.badPixelPct = 100.0 * double(bad) / double(pixels);
  e.coveredRmse = covered ? std::sqrt(coveredSq / double(covered * 3)) : 0.0;
  e.coveredPct = 100.0 * double(covered) / double(pixels);
  return e;
}

double drawnRmse(const ImageF& a, const ImageF& b) {
  if (a.size != b.size || a.rgba.empty()) return 1.0;
  const int w = a.size.x, h = a.size.y;
  const auto covers = [w](const ImageF& im, int x, int y) { return im.rgba[(size_t(y) * w + x) * 4 + 3] > 0.5f; };
  const auto touches = [&](const ImageF& im, int x, int y) {
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int u = x + dx, v = y + dy;
        if (u >= 0 && v >= 0 && u < w && v < h && covers(im, u, v)) return true;
      }
    return false;
  };
  double sumSq = 0.0;
  size_t counted = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const bool inA = covers(a, x, y), inB = covers(b, x, y);
      if (!inA && !inB) continue;
      if (inA != inB && touches(inA ? b : a, x, y)) continue;
      const size_t i = size_t(y) * w + x;
      for (int c = 0; c < 3; ++c) {
        const double d = double(clamp01(a.rgba[i * 4 + c])) - clamp01(b.rgba[i * 4 + c]);
        sumSq += d * d;
      }
      ++counted;
    }
  return counted ? std::sqrt(sumSq / double(counted * 3)) : 0.0;
}

size_t countNonFinite(const ImageF& image) {
  return size_t(std::count_if(image.rgba.begin(), image.rgba.end(), [](float v) { return !std::isfinite(v); }));
}

ImageF downsample(const ImageF& in, int f) {
  if (f <= 1) return in;
  ImageF out;
  out.size = in.size / f;
  out.rgba.assign(size_t(out.size.x) * out.size.y * 4, 0.0f);
  const float w = 1.0f / float(f * f);
  for (int y = 0; y < out.size.y; ++y)
    for (int x = 0; x < out.size.x; ++x)
      for (int sy = 0; sy < f; ++sy)
        for (int sx = 0; sx < f; ++sx)
          for (int c = 0; c < 4; ++c) out.at(x, y)[c] += in.at(x * f + sx, y * f + sy)[c] * w;
  return out;
}

ImageF diffImage(const ImageF& a, const ImageF& b, float gain) {
  ImageF d;
  d.size = a.size;
  d.rgba.resize(a.rgba.size());
  for (size_t i = 0; i < a.rgba.size(); ++i)
    d.rgba[i] = (i % 4 == 3) ? 1.0f
                : !std::isfinite(a.rgba[i]) || !std::isfinite(b.rgba[i])
                    ? 1.0f
                    : std::min(1.0f, std::abs(a.rgba[i] - b.rgba[i]) * gain);
  return d;
}

std::string writePng(const std::string& path, const ImageF& image) {
  std::vector<unsigned char> rgb(size_t(image.size.x) * image.size.y * 3);
  for (size_t i = 0, n = rgb.size() / 3; i < n; ++i)
    for (int c = 0; c < 3; ++c) rgb[i * 3 + c] = (unsigned char)std::lround(clamp01(image.rgba[i * 4 + c]) * 255.0f);
  makeParentFolder(path);  // a failure shows as the write's own error below
  const std::string tmp = path + ".tmp";
  if (!stbi_write_png(tmp.c_str(), image.size.x, image.size.y, 3, rgb.data(), image.size.x * 3))
    return path + ": cannot write PNG (does the folder exist and is it writable?)";
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  return ec ? path + ": cannot rename from " + tmp + ": " + ec.message() : std::string();
}

std::string readImage(const std::string& path, ImageF& image) {
  int w = 0, h = 0, n = 0;
  unsigned char* px = stbi_load(path.c_str(), &w, &h, &n, 4);
  if (!px)
    return path + ": cannot read image (" + std::string(stbi_failure_reason() ? stbi_failure_reason() : "?") + ")";
  image.size = {w, h};
  image.rgba.resize(size_t(w) * h * 4);
  for (size_t i = 0; i < image.rgba.size(); ++i) image.rgba[i] = px[i] / 255.0f;
  stbi_image_free(px);
  return {};
}

}  // namespace shadelab

// image_check FILE.png [--min-stddev S] [--min-colors N] [--color R,G,B --min-pixels P]: exits
// non-zero if the image is blank (one flat colour), has fewer distinct colours than expected, or
// fewer than P pixels within 12/255 of the colour R,G,B (0-255; a progress bar's fill, say).
// --crop X,Y,W,H looks at that part only (a window's viewport). For window and page screenshots.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <string>

#include "app/measure/image.h"

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr,
                 "usage: image_check FILE.png [--min-stddev S] [--min-colors N] [--min-pixels N --color R,G,B] "
                 "[--crop X,Y,W,H]\n");
    return 2;
  }
  double minStddev = 0.05;
  size_t minColors = 64, minPixels = 0;
  int want[3] = {-1, -1, -1};
  int crop[4] = {0, 0, 0, 0};  // x, y, w, h of the part to look at (w = 0: the whole image)
  for (int i = 2; i + 1 < argc; i += 2) {
    if (std::string(argv[i]) == "--min-stddev") minStddev = std::atof(argv[i + 1]);
    if (std::string(argv[i]) == "--min-colors") minColors = size_t(std::atoi(argv[i + 1]));
    if (std::string(argv[i]) == "--min-pixels") minPixels = size_t(std::atoi(argv[i + 1]));
    if (std::string(argv[i]) == "--crop" &&
        std::sscanf(argv[i + 1], "%d,%d,%d,%d", &crop[0], &crop[1], &crop[2], &crop[3]) != 4) {
      std::fprintf(stderr, "--crop: expected X,Y,W,H in pixels\n");
      return 2;
    }
    if (std::string(argv[i]) == "--color" && std::sscanf(argv[i + 1], "%d,%d,%d", &want[0], &want[1], &want[2]) != 3) {
      std::fprintf(stderr, "--color: expected R,G,B in 0..255\n");
      return 2;
    }
  }
  shadelab::ImageF img;
  if (auto err = shadelab::readImage(argv[1], img); !err.empty()) {
    std::fprintf(stderr, "%s\n", err.c_str());
    return 1;
  }
  double sum = 0, sum2 = 0;
  std::set<unsigned> colors;
  size_t matching = 0;
  if (crop[2] > 0) {  // the part asked for, clipped to the image
    shadelab::ImageF part;
    const int x0 = std::clamp(crop[0], 0, img.size.x), y0 = std::clamp(crop[1], 0, img.size.y);
    part.size = {std::clamp(crop[2], 0, img.size.x - x0), std::clamp(crop[3], 0, img.size.y - y0)};
    for (int y = y0; y < y0 + part.size.y; ++y)
      part.rgba.insert(part.rgba.end(), img.rgba.begin() + (size_t(y) * img.size.x + x0) * 4,
                       img.rgba.begin() + (size_t(y) * img.size.x + x0 + part.size.x) * 4);
    img = std::move(part);
  }
  const size_t n = img.rgba.size() / 4;
  if (n == 0) {
    std::fprintf(stderr, "%s: nothing to look at (the crop is outside the image)\n", argv[1]);
    return 1;
  }
  for (size_t i = 0; i < n; ++i) {
    const float* p = &img.rgba[i * 4];
    if (want[0] >= 0) {
      bool near = true;
      for (int c = 0; c < 3; ++c) near &= std::abs(p[c] * 255.0f - float(want[c])) <= 12.0f;
      matching += near;
    }
    const double l = (p[0] + p[1] + p[2]) / 3.0;
    sum += l;
    sum2 += l * l;
    colors.insert(unsigned(p[0] * 255) << 16 | unsigned(p[1] * 255) << 8 | unsigned(p[2] * 255));
  }
  const double mean = sum / double(n), stddev = std::sqrt(std::max(0.0, sum2 / double(n) - mean * mean));
  std::printf("%s: %dx%d, mean %.3f, stddev %.3f, %zu colours\n", argv[1], img.size.x, img.size.y, mean, stddev,
              colors.size());
  if (stddev < minStddev || colors.size() < minColors) {
    std::fprintf(stderr, "%s: looks blank (stddev %.3f < %.3f or colours %zu < %zu)\n", argv[1], stddev, minStddev,
                 colors.size(), minColors);
    return 1;
  }
  if (want[0] >= 0) {
    std::printf("%s: %zu pixels of %d,%d,%d\n", argv[1], matching, want[0], want[1], want[2]);
    if (matching < minPixels) {
      std::fprintf(stderr, "%s: %zu pixels of %d,%d,%d, expected at least %zu\n", argv[1], matching, want[0], want[1],
                   want[2], minPixels);
      return 1;
    }
  }
  return 0;
}

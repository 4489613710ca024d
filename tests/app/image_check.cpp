// image_check FILE.png [--min-stddev S] [--min-colors N]: exits non-zero if the image is blank
// (one flat colour) or has fewer distinct colours than expected. For window screenshots.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <string>

#include "measure/image.h"

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: image_check FILE.png [--min-stddev S] [--min-colors N]\n");
    return 2;
  }
  double minStddev = 0.05;
  size_t minColors = 64;
  for (int i = 2; i + 1 < argc; i += 2) {
    if (std::string(argv[i]) == "--min-stddev") minStddev = std::atof(argv[i + 1]);
    if (std::string(argv[i]) == "--min-colors") minColors = size_t(std::atoi(argv[i + 1]));
  }
  shadelab::ImageF img;
  if (auto err = shadelab::readImage(argv[1], img); !err.empty()) {
    std::fprintf(stderr, "%s\n", err.c_str());
    return 1;
  }
  double sum = 0, sum2 = 0;
  std::set<unsigned> colors;
  const size_t n = img.rgba.size() / 4;
  for (size_t i = 0; i < n; ++i) {
    const float* p = &img.rgba[i * 4];
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
  return 0;
}

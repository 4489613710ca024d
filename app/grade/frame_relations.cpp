#include "app/grade/frame_relations.h"
#include "app/util/format.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace shadelab {

namespace {

constexpr int kMostShift = 4;  // whole pixels searched each way

bool usable(const float* p) {
  return !(p[3] <= 0.5f) && std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
}

// RMS over RGB of student(x, y) against `transform` of the solution, sampled where `source` puts
// (x, y) in the solution's frame; NaN when fewer than half the pixels both cover take part.
// A template over both, so that the per-pixel calls inline: the shift search alone runs this over
// the frame eighty times.
template <class Source, class Transform>
double residualOf(const ImageF& student, const ImageF& solution, size_t pixels, const Source& source,
                  const Transform& transform) {
  double sum = 0.0;
  size_t n = 0;
  double t[3];
  for (int y = 0; y < student.size.y; ++y)
    for (int x = 0; x < student.size.x; ++x) {
      const float* s = student.at(x, y);
      int sx = x, sy = y;
      if (!usable(s) || !source(x, y, sx, sy)) continue;
      const float* p = solution.at(sx, sy);
      if (!usable(p)) continue;
      transform(p, t);
      for (int c = 0; c < 3; ++c) {
        const double d = std::min(1.0, std::abs(double(s[c]) - t[c]));
        sum += d * d;
      }
      ++n;
    }
  return 2 * n >= pixels && n ? std::sqrt(sum / double(3 * n)) : std::nan("");
}

constexpr auto inPlace = [](int x, int y, int& sx, int& sy) {
  sx = x;
  sy = y;
  return true;
};

// How much simpler explanations are preferred: a fitted one must fit clearly better to win.
double plainness(const std::string& kind) {
  if (kind == "affine") return 1.4;
  if (kind == "shifted") return 1.2;
  if (kind == "squared" || kind == "square-root") return 1.1;
  return 1.0;
}

std::string number(double v) { return formatSignificant(v, 2); }

std::vector<std::string> channelNames(const std::string& channels) {
  std::vector<std::string> out;
  size_t at = 0;
  while (out.size() < 3) {
    const size_t comma = channels.find(", ", at);
    out.push_back(channels.substr(at, comma == std::string::npos ? std::string::npos : comma - at));
    if (comma == std::string::npos) break;
    at = comma + 2;
  }
  while (out.size() < 3) out.push_back("channel " + std::to_string(out.size() + 1));
  return out;
}

int channelIndex(char c) { return c == 'r' ? 0 : c == 'g' ? 1 : 2; }

}  // namespace

std::vector<FrameRelation> relateFrames(const ImageF& student, const ImageF& solution, const ViewRange& range,
                                        double fits) {
  std::vector<FrameRelation> out;
  if (student.size != solution.size || student.rgba.empty()) return out;
  const glm::ivec2 size = student.size;
  const double sum = range.bounded ? double(range.low) + range.high : 1.0;

  // The distance and the moments an affine fit needs, over the pixels both cover.
  size_t pixels = 0;
  double st = 0.0, s1 = 0.0, t1 = 0.0, tt = 0.0, dd = 0.0;
  for (int y = 0; y < size.y; ++y)
    for (int x = 0; x < size.x; ++x) {
      const float *s = student.at(x, y), *p = solution.at(x, y);
      if (!usable(s) || !usable(p)) continue;
      ++pixels;
      for (int c = 0; c < 3; ++c) {
        const double d = std::min(1.0, std::abs(double(s[c]) - p[c]));
        dd += d * d;
        st += double(s[c]) * p[c];
        s1 += s[c];
        t1 += p[c];
        tt += double(p[c]) * p[c];
      }
    }
  if (pixels == 0) return out;
  const double distance = std::sqrt(dd / double(3 * pixels));
  if (distance <= kFramesDiffer) return out;  // frames that agree relate trivially

  const auto consider = [&](FrameRelation r, const auto& source, const auto& transform) {
    r.residual = residualOf(student, solution, pixels, source, transform);
    if (std::isfinite(r.residual) && r.residual <= fits * distance) out.push_back(r);
  };

  consider({"complement"}, inPlace, [&](const float* p, double* t) {
    for (int c = 0; c < 3; ++c) t[c] = sum - p[c];
  });
  consider(
      {"mirrored-x"},
      [&](int x, int y, int& sx, int& sy) {
        sx = size.x - 1 - x;
        sy = y;
        return true;
      },
      [](const float* p, double* t) { std::copy(p, p + 3, t); });
  consider(
      {"mirrored-y"},
      [&](int x, int y, int& sx, int& sy) {
        sx = x;
        sy = size.y - 1 - y;
        return true;
      },
      [](const float* p, double* t) { std::copy(p, p + 3, t); });
  for (const char* pair : {"rg", "rb", "gb"}) {
    const int i = channelIndex(pair[0]), j = channelIndex(pair[1]);
    consider({std::string("swapped-") + pair}, inPlace, [&](const float* p, double* t) {
      std::copy(p, p + 3, t);
      std::swap(t[i], t[j]);
    });
  }
  for (const char* set : {"r", "g", "b", "rg", "rb", "gb"}) {
    const std::string flipped = set;
    bool turned[3];
    for (int c = 0; c < 3; ++c) turned[c] = flipped.find("rgb"[c]) != std::string::npos;
    consider({"flipped-" + flipped}, inPlace, [&](const float* p, double* t) {
      for (int c = 0; c < 3; ++c) t[c] = turned[c] ? sum - p[c] : p[c];
    });
  }
  consider({"squared"}, inPlace, [](const float* p, double* t) {
    for (int c = 0; c < 3; ++c) t[c] = double(p[c]) * p[c];
  });
  consider({"square-root"}, inPlace, [](const float* p, double* t) {
    for (int c = 0; c < 3; ++c) t[c] = std::sqrt(std::max(0.0, double(p[c])));
  });
  // The best whole-pixel shift (the shortest among equals), then whether it holds.
  FrameRelation shift{"shifted"};
  double bestShift = std::nan("");
  for (int dy = -kMostShift; dy <= kMostShift; ++dy)
    for (int dx = -kMostShift; dx <= kMostShift; ++dx) {
      if (!dx && !dy) continue;
      const double r = residualOf(
          student, solution, pixels,
          [&](int x, int y, int& sx, int& sy) {
            sx = x - dx;
            sy = y - dy;
            return sx >= 0 && sy >= 0 && sx < size.x && sy < size.y;
          },
          [](const float* p, double* t) { std::copy(p, p + 3, t); });
      if (std::isfinite(r) && !(r >= bestShift * (1.0 - 1e-9))) {
        bestShift = r;
        shift.a = dx;
        shift.b = dy;
      }
    }
  if (std::isfinite(bestShift) && bestShift <= fits * distance) {
    shift.residual = bestShift;
    out.push_back(shift);
  }
  // a * solution + b, fitted by least squares over every channel.
  const double n = double(3 * pixels), variance = tt / n - (t1 / n) * (t1 / n);
  if (variance > 1e-6) {
    FrameRelation affine{"affine"};
    affine.a = (st / n - (s1 / n) * (t1 / n)) / variance;
    affine.b = s1 / n - affine.a * t1 / n;
    if (std::abs(affine.a - 1.0) > 0.05 || std::abs(affine.b) > 0.02)
      consider(affine, inPlace, [&](const float* p, double* t) {
        for (int c = 0; c < 3; ++c) t[c] = affine.a * p[c] + affine.b;
      });
  }
  std::stable_sort(out.begin(), out.end(), [](const FrameRelation& x, const FrameRelation& y) {
    return x.residual * plainness(x.kind) < y.residual * plainness(y.kind);
  });
  return out;
}

ImageF composeChanges(const ImageF& solution, const ImageF& a, const ImageF& b, const ViewRange& range) {
  ImageF out = solution;
  if (a.size != solution.size || b.size != solution.size) return out;
  const float low = range.bounded ? range.low : 0.0f, high = range.bounded ? range.high : INFINITY;
  for (size_t i = 0; i < out.rgba.size(); i += 4)
    for (size_t c = 0; c < 3; ++c)
      out.rgba[i + c] = std::clamp(a.rgba[i + c] + b.rgba[i + c] - solution.rgba[i + c], low, high);
  return out;
}

bool sameRelation(const FrameRelation& x, const FrameRelation& y) {
  if (x.kind != y.kind) return false;
  if (x.kind == "shifted") return std::abs(x.a - y.a) <= 1.0 && std::abs(x.b - y.b) <= 1.0;
  if (x.kind == "affine")
    return std::abs(x.a - y.a) <= 0.15 * std::max(std::abs(x.a), 0.1) && std::abs(x.b - y.b) <= 0.08;
  return true;
}

std::string describeRelation(const FrameRelation& r, const ViewRange& range, const std::string& channels) {
  const std::vector<std::string> names = channelNames(channels);
  const double sum = range.bounded ? double(range.low) + range.high : 1.0;
  if (r.kind == "complement")
    return "the solution's turned over (where it holds x, yours holds " + number(sum) + " - x)";
  if (r.kind == "mirrored-x") return "the solution's mirrored left to right";
  if (r.kind == "mirrored-y") return "the solution's turned upside down";
  if (r.kind == "squared") return "the solution's squared";
  if (r.kind == "square-root") return "the square root of the solution's";
  if (r.kind == "shifted") return "the solution's moved by (" + number(r.a) + ", " + number(r.b) + ") pixels";
  if (r.kind == "affine") {
    if (std::abs(r.b) <= 0.02) return "the solution's scaled by " + number(r.a);
    if (std::abs(r.a - 1.0) <= 0.05)
      return "the solution's " + std::string(r.b > 0 ? "plus " : "minus ") + number(std::abs(r.b));
    return number(r.a) + " times the solution's " + (r.b > 0 ? "plus " : "minus ") + number(std::abs(r.b));
  }
  if (r.kind.rfind("swapped-", 0) == 0)
    return "the solution's with its " + names[size_t(channelIndex(r.kind[8]))] + " and " +
           names[size_t(channelIndex(r.kind[9]))] + " exchanged";
  if (r.kind.rfind("flipped-", 0) == 0) {
    std::string which;
    for (size_t i = 8; i < r.kind.size(); ++i)
      which += (which.empty() ? "" : " and ") + names[size_t(channelIndex(r.kind[i]))];
    return "the solution's with its " + which + " turned over (x becomes " + number(sum) + " - x)";
  }
  return "the solution's, " + r.kind;
}

std::string relationCause(const FrameRelation& r) {
  if (r.kind == "complement")
    return "what your function returns is the opposite of what is asked: a comparison the wrong way round, a "
           "condition inverted, or the complementary quantity returned";
  if (r.kind == "mirrored-x" || r.kind == "mirrored-y")
    return "a coordinate runs the wrong way: its sign, or 1 - u where u was meant (or the reverse)";
  if (r.kind == "squared") return "a factor is applied twice (the value multiplied by itself somewhere)";
  if (r.kind == "square-root") return "a factor the solution applies twice is applied once";
  if (r.kind == "shifted")
    return "every position is offset by a constant: a sample grid that is not centred, or a coordinate off by "
           "half a texel or a pixel";
  if (r.kind == "affine") {
    if (std::abs(r.b) <= 0.02) return "a factor is missing or extra (a weight, a normalisation, a strength)";
    if (std::abs(r.a - 1.0) <= 0.05) return "a constant term is added or left out";
    return "a remapping (between [-1, 1] and [0, 1], say, or a scale with an offset) is applied where it should not "
           "be, or left out";
  }
  if (r.kind.rfind("swapped-", 0) == 0)
    return "two components are exchanged: a vector built or read in the wrong order, or a matrix's rows taken for "
           "its columns";
  if (r.kind.rfind("flipped-", 0) == 0)
    return "a component has the wrong sign: an axis reversed (a tangent or bitangent pointing the other way, the "
           "operands of a cross product exchanged, a coordinate's sign)";
  return "";
}

}  // namespace shadelab

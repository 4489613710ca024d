#include "app/grade/frame_properties.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace shadelab {

namespace {

constexpr int kMostShift = 4;           // pixels searched each way for the best-matching shift
constexpr double kClearlyBetter = 0.5;  // a shift counts when it halves the mismatch of none
constexpr size_t kFewestPixels = 16;    // a mask or an edge smaller than this says nothing

bool finitePixel(const float* p) { return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]); }
double value(const float* p) { return (double(p[0]) + p[1] + p[2]) / 3.0; }
bool covered(const float* p) { return !(p[3] <= 0.5f); }  // a NaN alpha counts as covered: its pixel is the student's

}  // namespace

std::vector<std::pair<std::string, double>> FrameProperties::metrics(const ImageF& frame) const {
  const double pixels = std::max<double>(1.0, double(frame.size.x) * frame.size.y);
  return {{"non_finite_pct", 100.0 * double(nonFinitePixels()) / pixels},
          {"out_of_range_pct", outOfRangePct},
          {"umbra_level", umbraLevel},
          {"lit_level", litLevel},
          {"edge_shift_px", edgeShiftPx},
          {"edge_width_change", std::abs(edgeWidthRatio - 1.0)}};
}

std::string FrameProperties::nonFiniteText() const {
  if (nonFinitePixels() == 0) return {};
  std::string what;
  if (nanPixels) what += std::to_string(nanPixels) + " NaN";
  if (infPixels) what += std::string(what.empty() ? "" : " and ") + std::to_string(infPixels) + " Inf";
  return what + " pixel" + (nonFinitePixels() == 1 ? "" : "s") + " in x " + std::to_string(nonFiniteBox.x) + "-" +
         std::to_string(nonFiniteBox.z) + ", y " + std::to_string(nonFiniteBox.y) + "-" +
         std::to_string(nonFiniteBox.w);
}

FrameProperties measureFrameProperties(const ImageF& student, const ImageF& solution, const ImageF* truth,
                                       const ViewRange& range) {
  FrameProperties out;
  const glm::ivec2 size = student.size;
  out.nonFiniteBox = {size.x, size.y, -1, -1};
  for (int y = 0; y < size.y; ++y)
    for (int x = 0; x < size.x; ++x) {
      const float* p = student.at(x, y);
      if (finitePixel(p) && std::isfinite(p[3])) continue;
      const bool nan = std::isnan(p[0]) || std::isnan(p[1]) || std::isnan(p[2]) || std::isnan(p[3]);
      ++(nan ? out.nanPixels : out.infPixels);
      out.nonFiniteBox = {std::min(out.nonFiniteBox.x, x), std::min(out.nonFiniteBox.y, y),
                          std::max(out.nonFiniteBox.z, x), std::max(out.nonFiniteBox.w, y)};
    }
  if (out.nonFinitePixels() == 0) out.nonFiniteBox = glm::ivec4(0);
  if (solution.size != size) return out;
  if (truth && truth->size != size) truth = nullptr;

  // The best-matching shift: student(x + dx, y + dy) against solution(x, y) over the pixels both
  // cover, finite in both.
  const auto mismatch = [&](int dx, int dy) {
    double sum = 0.0;
    size_t n = 0;
    for (int y = std::max(0, -dy); y < std::min(size.y, size.y - dy); ++y)
      for (int x = std::max(0, -dx); x < std::min(size.x, size.x - dx); ++x) {
        const float *s = student.at(x + dx, y + dy), *p = solution.at(x, y);
        if (!covered(s) || !covered(p) || !finitePixel(s) || !finitePixel(p)) continue;
        const double d = value(s) - value(p);
        sum += d * d;
        ++n;
      }
    return n ? sum / double(n) : std::numeric_limits<double>::infinity();
  };
  const double none = mismatch(0, 0);
  double best = none;
  for (int dy = -kMostShift; dy <= kMostShift; ++dy)
    for (int dx = -kMostShift; dx <= kMostShift; ++dx) {
      const double m = (dx || dy) ? mismatch(dx, dy) : none;
      // Of shifts that match equally (an edge along one axis matches at any shift along it), the shortest.
      const bool tie = m <= best * (1.0 + 1e-9) &&
                       dx * dx + dy * dy < out.edgeShift.x * out.edgeShift.x + out.edgeShift.y * out.edgeShift.y;
      if (m < best * (1.0 - 1e-9) || tie) {
        best = std::min(best, m);
        out.edgeShift = {dx, dy};
      }
    }
  if (!(none > 1e-6 && best < kClearlyBetter * none)) out.edgeShift = glm::ivec2(0);
  out.edgeShiftPx = std::sqrt(double(out.edgeShift.x * out.edgeShift.x + out.edgeShift.y * out.edgeShift.y));

  if (!range.bounded) return out;
  const double low = range.low, span = double(range.high) - range.low;
  size_t outside = 0, coveredPixels = 0, umbraN = 0, litN = 0, studentEdge = 0, solutionEdge = 0;
  double umbra = 0.0, lit = 0.0;
  std::vector<double> outsideValues;
  const auto inside = [&](double v) { return v > low + 0.05 * span && v < low + 0.95 * span; };
  for (int y = 0; y < size.y; ++y)
    for (int x = 0; x < size.x; ++x) {
      const float *s = student.at(x, y), *p = solution.at(x, y);
      if (!covered(p) || !finitePixel(p)) continue;
      ++coveredPixels;
      solutionEdge += inside(value(p));
      if (!finitePixel(s)) continue;
      const double v = value(s);
      const double eps = 2e-3 * span;
      if (std::any_of(s, s + 3, [&](float c) { return c < low - eps || c > low + span + eps; })) {
        ++outside;
        outsideValues.push_back(v);
      }
      studentEdge += inside(v);
      const double t = truth && !(truth->at(x, y)[3] < 0.5f) ? truth->at(x, y)[0] : value(p);
      if (value(p) <= low + 0.02 * span && t <= low + 0.01 * span) {
        umbra += (v - low) / span;
        ++umbraN;
      }
      if (value(p) >= low + 0.98 * span && t >= low + 0.99 * span) {
        lit += (low + span - v) / span;
        ++litN;
      }
    }
  out.outOfRangePct = coveredPixels ? 100.0 * double(outside) / double(coveredPixels) : 0.0;
  if (!outsideValues.empty()) {
    auto middle = outsideValues.begin() + std::ptrdiff_t(outsideValues.size() / 2);
    std::nth_element(outsideValues.begin(), middle, outsideValues.end());
    out.outsideMedian = *middle;
  }
  out.umbraLevel = umbraN >= kFewestPixels ? umbra / double(umbraN) : 0.0;
  out.litLevel = litN >= kFewestPixels ? lit / double(litN) : 0.0;
  out.edgeWidthRatio = solutionEdge >= kFewestPixels ? double(studentEdge) / double(solutionEdge) : 1.0;
  return out;
}

namespace {

// The squared difference of two pixels both frames cover, summed over RGB (each channel's at most
// 1): a pixel non-finite in one and not the other counts as the largest, one non-finite in both as
// none.
double squaredDifference(const float* p, const float* q) {
  const bool fp = finitePixel(p), fq = finitePixel(q);
  if (!fp || !fq) return fp == fq ? 0.0 : 3.0;
  double sum = 0.0;
  for (int c = 0; c < 3; ++c) {
    const double d = std::min(1.0, std::abs(double(p[c]) - q[c]));
    sum += d * d;
  }
  return sum;
}

// Whether `im` covers a pixel of the 8-neighbourhood of (x, y), or (x, y) itself.
bool touches(const ImageF& im, int x, int y) {
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      const int u = x + dx, v = y + dy;
      if (u >= 0 && v >= 0 && u < im.size.x && v < im.size.y && covered(im.at(u, v))) return true;
    }
  return false;
}

// The RMS difference over the pixels both frames cover, or (`eitherDraws`) over those either
// covers, a pixel only one covers counting as the largest difference unless it touches the other's
// surface (a silhouette moved by a pixel).
double distance(const ImageF& a, const ImageF& b, bool eitherDraws) {
  if (a.size != b.size || a.rgba.empty()) return 1.0;
  double sum = 0.0;
  size_t n = 0;
  for (int y = 0; y < a.size.y; ++y)
    for (int x = 0; x < a.size.x; ++x) {
      const float *p = a.at(x, y), *q = b.at(x, y);
      const bool inA = covered(p), inB = covered(q);
      if (inA != inB && (!eitherDraws || touches(inA ? b : a, x, y))) continue;
      if (!inA && !inB) continue;
      ++n;
      sum += inA == inB ? squaredDifference(p, q) : 3.0;
    }
  return n ? std::sqrt(sum / double(n * 3)) : 0.0;
}

}  // namespace

double frameDistance(const ImageF& a, const ImageF& b) { return distance(a, b, false); }

double drawnDistance(const ImageF& a, const ImageF& b) { return distance(a, b, true); }

}  // namespace shadelab

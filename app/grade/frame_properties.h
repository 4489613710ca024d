// Properties of a student's frame that isolate a cause, measured against the solution's frame (and
// the lab's truth where there is one): the evidence a diagnosis and a conditional hint rest on.
//
//   non-finite pixels   NaN and Inf counted apart, with the box they fill: 0/0, a normalize of a
//                       zero vector and a log of 0 each leave their own mark
//   out of range        values outside what the view can hold (visibility above 1 or below 0)
//   umbra / lit level   how far the student's frame stays from 0 where the truth and the solution
//                       are in full shadow, and from 1 where both are fully lit
//   edge shift          the whole-pixel shift of the student's frame that best matches the
//                       solution's (a cross-correlation's peak): a grid not centred moves every edge
//   edge width          the pixels strictly between the range's ends, the student's over the
//                       solution's: a kernel too wide or too narrow
//
// Every function here is pure CPU work on images, so it is unit-tested without a context.
#pragma once
#include <cstddef>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>
#include <string>
#include <utility>
#include <vector>

#include "app/measure/image.h"

namespace shadelab {

struct FrameProperties {
  size_t nanPixels = 0, infPixels = 0;  // pixels with a NaN (or an Inf and no NaN) in a channel
  glm::ivec4 nonFiniteBox{0};           // x0, y0, x1, y1 (inclusive) of those pixels
  // The rest read as right (0, or a ratio of 1) where they do not apply: no range, an empty mask,
  // no edge in the solution.
  double outOfRangePct = 0.0;   // covered pixels with a channel outside [low, high], in percent
  double outsideMedian = 0.0;   // the median of those pixels' values (mean of RGB): where they went
  double umbraLevel = 0.0;      // mean (value - low) / (high - low) over the umbra mask; 0 when right
  double litLevel = 0.0;        // mean (high - value) / (high - low) over the lit mask; 0 when right
  glm::ivec2 edgeShift{0};      // the best-matching shift of the student's frame, in pixels
  double edgeShiftPx = 0.0;     // its length: 0 when no shift matches clearly better than none
  double edgeWidthRatio = 1.0;  // pixels strictly inside the range, the student's over the solution's

  size_t nonFinitePixels() const { return nanPixels + infPixels; }
  // The numbers checks can use, lower is better: non_finite_pct, out_of_range_pct, umbra_level,
  // lit_level, edge_shift_px, edge_width_change (|ratio - 1|).
  std::vector<std::pair<std::string, double>> metrics(const ImageF& frame) const;
  // "37 NaN pixels in x 12-40, y 30-52" (empty when there are none).
  std::string nonFiniteText() const;
};

struct ViewRange {
  bool bounded = false;
  float low = 0.0f, high = 1.0f;
};

// `truth` may be null (no truth, or one of another size): the masks then come from the solution's
// frame alone. A truth's first channel is taken as the value a right frame holds there.
FrameProperties measureFrameProperties(const ImageF& student, const ImageF& solution, const ImageF* truth,
                                       const ViewRange& range);

// How far two frames are apart, for telling which of several frames a student's is closest to:
// the RMS difference of RGB over the pixels both cover, where a pixel non-finite in one frame and
// not the other counts as the largest difference (1) and one non-finite in both as none.
double frameDistance(const ImageF& a, const ImageF& b);
// Two frames differ when frameDistance puts them further apart than one 8-bit step.
constexpr double kFramesDiffer = 0.004;

// frameDistance over the pixels either frame covers: a pixel only one covers counts as the largest
// difference, unless it touches (8-neighbourhood) what the other covers (a silhouette moved by a
// pixel). A frame that draws nothing is far from one that draws, as frameDistance alone would not
// say: what the solution's slips are told apart by (grade/configuration_frames.h).
double drawnDistance(const ImageF& a, const ImageF& b);

}  // namespace shadelab

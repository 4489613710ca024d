// How a student's frame relates to the solution's, found without being told the mistake: the
// evidence a diagnosis has for mistakes no rubric lists.
//
// Each relation is a transform of the solution's frame; it holds when the transformed frame lies
// far closer to the student's than the solution's does (the residual against the distance):
//
//   complement     every channel c -> low + high - c        a comparison or the result turned over
//   affine         a * c + b (a scaled, b an offset)        a factor or a term missing or extra
//   squared        c * c, and square-root sqrt(c)           a factor applied twice, or once too few
//   mirrored x/y   the frame mirrored left-right, up-down   a coordinate's sign, a 1 - u
//   shifted        moved by (dx, dy) whole pixels           a grid or coordinate off by a step
//   swapped        two channels exchanged                   two components of a vector exchanged
//   flipped        one or two channels turned over          one component's sign (a normal's x, say)
//
// Pure CPU work on images, unit-tested without a context.
#pragma once
#include <string>
#include <vector>

#include "app/grade/frame_properties.h"
#include "app/measure/image.h"

namespace shadelab {

struct FrameRelation {
  // "complement", "affine", "squared", "square-root", "mirrored-x", "mirrored-y", "shifted",
  // "swapped-rg" (-rb, -gb), "flipped-r" (-g, -b, -rg, -rb, -gb)
  std::string kind;
  double a = 1.0, b = 0.0;  // affine: the scale and the offset; shifted: dx and dy in pixels
  double residual = 0.0;    // frameDistance-like RMS of the student's frame to the transformed solution's
};

// How well a frame must be explained to count: a relation (or another drawing of the solution)
// fits the student's frame when what is left is at most this share of the frames' distance.
constexpr double kFrameFit = 0.35;

// The relations that hold between the frames, best first: those whose residual is at most
// `fits` times the frames' distance (nothing when the frames already agree, within one 8-bit step).
std::vector<FrameRelation> relateFrames(const ImageF& student, const ImageF& solution, const ViewRange& range,
                                        double fits = kFrameFit);

// The same relation, as the two agree (the same kind; an affine's or a shift's numbers close).
bool sameRelation(const FrameRelation& x, const FrameRelation& y);

// The solution's frame with two other frames' changes to it added: solution + (a - solution) +
// (b - solution), clamped to the view's range (to [0, inf) when it has none). Where the two
// changes touch different pixels this is the frame both mistakes would draw together.
ImageF composeChanges(const ImageF& solution, const ImageF& a, const ImageF& b, const ViewRange& range);

// For a student, in the exercise's terms: "the solution's turned over (low + high - x)",
// "the solution's scaled by 0.5", ... `channels` names the view's three channels ("red, green,
// blue", or "the normal's x, y, z").
std::string describeRelation(const FrameRelation& r, const ViewRange& range, const std::string& channels);
// What such a relation usually comes from, in a sentence that names no formula.
std::string relationCause(const FrameRelation& r);

}  // namespace shadelab

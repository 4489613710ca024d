// What a frame's properties (grade/frame_properties.h) say to a student, for the diagnosis: the
// usual causes of NaN and Inf pixels, and of values out of range, a lit region not lit or edges of
// the wrong width; or, where the cause is not one, only what was seen.
#pragma once
#include <string>

#include "app/grade/frame_properties.h"
#include "app/grade/grading.h"

namespace shadelab {

// "Your frame holds non-finite values in 'a': ... A NaN comes from 0/0 ..."
std::string nonFiniteCause(const ConfigurationResult& c);

struct Cause {
  std::string tag, text;  // ExerciseResult::explanation and diagnosis
};
// What a configuration's frame properties say, or nothing (an empty text); `range` is the
// configuration's (its "range"), named where values leave it.
Cause propertyCause(const ConfigurationResult& c, const ViewRange& range);

// What a configuration's frame properties measure, without a cause: "In 'a', where the truth and
// the solution are fully lit, yours is 0.63 of the way to shadow." ("" when nothing stands out).
std::string propertyObservation(const ConfigurationResult& c, const ViewRange& range);

}  // namespace shadelab

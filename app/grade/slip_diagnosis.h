// The solution's slips as evidence for a diagnosis (grade/diagnosis.h, step 3): the slips drawn
// in every configuration (grade/configuration_frames.h: drawSlips) against the student's frames.
// A slip is named when, in every drawn configuration, the student's frame is its frame wherever it
// differs from the solution's (within one 8-bit step, or kSlipFits of the student's distance; its
// very frame where the student's holds NaN or Inf), and is the solution's wherever the slip draws
// the solution's.
#pragma once
#include <string>

#include "app/grade/grading.h"
#include "app/grade/rubric.h"

namespace shadelab {

constexpr double kSlipFits = 0.1;

// What the slips whose frames are the student's say; nothing (found() false) when none is, or when
// those that fit about as well as the best have more than two different causes.
struct SlipFinding {
  std::string tag;       // "slip:KIND", the best slip's kind
  double misfit = 0.0;   // its summed distance to the student's frames over theirs to the solution's
  std::string what;      // "one slip: a comparison turned round, ..." (follows "the solution's with ")
  std::string evidence;  // " Your code may be written otherwise, ... (Evidence: where it shows ...)"
  bool found() const { return !what.empty(); }
};
SlipFinding findSlip(const Exercise& ex, const ExerciseResult& e);

}  // namespace shadelab

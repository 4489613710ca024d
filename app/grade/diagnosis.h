// One cause per exercise: what a student reads first under a failed exercise, in the terminal, the
// reports, the window's and the page's Check and the class page.
//
// The evidence, strongest first:
//   1. a known mistake of the rubric explains the frames: on the configurations where the mistake's
//      frame differs from the solution's, the student's frames lie clearly closer to the mistake's
//      (at most half as far) than to the solution's; the closest such mistake is named with the
//      rubric's own sentence;
//   2. the frame holds NaN or Inf (how many, where, and the usual causes of each);
//   3. a property of the frame says what is wrong: values outside the view's range, an umbra that
//      does not reach its low end or a lit region its high end, edges shifted against the
//      solution's, or edges wider or narrower than the solution's;
//   4. the points were lost in one configuration alone: what it uses and the others do not;
//   5. otherwise the check that lost most, and that no known mistake matches.
//
// Hints obey the same rule: a check's hint is shown only when the checks its cause needs passed or
// failed as the rubric says ("hint_when"); otherwise it stays silent rather than guessing.
#pragma once
#include "app/grade/grading.h"
#include "app/grade/rubric.h"

namespace shadelab {

// Clears the hints whose evidence is missing, then sets e.diagnosis (and e.mistake when a mistake
// of the rubric explains the frames). Leaves both empty when every point was earned.
void diagnose(const Exercise& ex, ExerciseResult& e);

// Which of the rubric's mistakes explains the frames of `e`: its index, or -1.
int explainingMistake(const Exercise& ex, const ExerciseResult& e);

}  // namespace shadelab

// Hints that speak only on evidence: a check's hint is shown when the checks its cause needs went
// as the rubric's "hint_when" says; otherwise it stays silent rather than guessing.
#pragma once
#include "app/grade/grading.h"

namespace shadelab {

// Clears every hint whose "hint_when" evidence is missing; messages that are not the hint (an
// error, a requirement) stay.
void silenceUnsupportedHints(ExerciseResult& e);

}  // namespace shadelab

// One cause per exercise: what a student reads first under a failed exercise, in the terminal, the
// reports, the window's and the page's Check and the class page.
//
// A diagnosis states its evidence and never names a cause the frames do not back: a wrong cause is
// worse than none. The evidence, strongest first:
//   1. a known mistake of the rubric whose frames agree with the student's: the student loses
//      points only where the mistake's frame differs from the solution's, and wherever it differs
//      the student's frame lies at most half as far from it as from the solution's. It is named
//      with the rubric's sentence (and its fix, where the rubric reveals fixes) and where it
//      shows; the untouched starter as the starter, a changed file that draws what the starter
//      draws as such. When a second mistake fits about as well, or a relation to the solution's
//      frames (5) fits clearly better, no mistake is named;
//   2. two known mistakes made together: each shows alone somewhere and agrees there;
//   3. one slip of the solution (grade/mutants.h: an operator or comparison turned round, a
//      constant changed, a call dropped, ...) whose frames are the student's in every configuration,
//      named by its kind and, where the rubric reveals fixes, what the solution has in its place;
//      no list needed. Two slips that draw the same frames are named together. The trace (3b)
//      follows it where there is one ("Traced line by line: ...");
//   3b. the student's own code traced beside the solution's on the probe's table (grade/trace.h):
//      the line where their values stop being the solution's, with what matches up to it and how
//      the value relates to the solution's result when a simple relation fits; it stands before a
//      listed mistake whose frames are only close to the student's (1). Then what the function
//      probed by itself shows (grade/function_probe.h), where the exercise has a probe;
//   4. the frame holds NaN or Inf (how many, where, and the usual causes of each);
//   5. a relation holds in every configuration that lost points (grade/frame_relations.h: turned
//      over, scaled, offset, squared, mirrored, shifted, components exchanged or turned over): the
//      relation, where it holds, and what it usually comes from;
//      Or, when it fits better, a setting at whose other value the solution draws the student's
//      frames in every losing configuration ("your frames are the solution's at strength 1").
//   6. a property of the frame: values outside the view's range, an umbra that does not reach
//      its low end or a lit region its high end, edges wider or narrower than the solution's;
//   7. where the frames differ, as a setting: "differ only where light_type is spot";
//   8. otherwise what the frames show: how many configurations differ, where most, and the check
//      that lost most.
//
// Hints obey the same rule: a check's hint is shown only when the checks its cause needs passed or
// failed as the rubric says ("hint_when"); otherwise it stays silent rather than guessing.
#pragma once
#include "app/grade/grading.h"
#include "app/grade/rubric.h"

namespace shadelab {

// Two explanations fit about as well when the second's misfit is within kDiagnosisClose times the
// first's (plus kDiagnosisSlack, for misfits near 0): the evidence cannot tell them apart.
constexpr double kDiagnosisClose = 1.5, kDiagnosisSlack = 0.005;

// "'a', 'b' and 'c'": the names of configurations as a diagnosis lists them.
std::string quotedList(const std::vector<std::string>& names);

// Clears the hints whose evidence is missing, then sets e.diagnosis, e.explanation (what it rests
// on) and e.mistake when a mistake of the rubric explains the frames. Leaves them empty when every
// point was earned.
void diagnose(const Exercise& ex, ExerciseResult& e);

// Whether the diagnosis of `e` would look at the solution's slips and some drawn configuration has
// none yet: the window's Check draws them then (grade/exercise_check.h) and diagnoses again.
bool slipsNeeded(const ExerciseResult& e);

// Which of the rubric's mistakes explains the frames of `e`: its index, or -1.
int explainingMistake(const Exercise& ex, const ExerciseResult& e);

}  // namespace shadelab

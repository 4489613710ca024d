// Exercises and their rubrics. An exercise lives in exercises/<lab>/<name>/:
//   statement.md   what to implement, the equation, what to read in the tutorial
//   starter/       a copy of the lab's shader file(s) with a marked TODO region, laid out like shaders/
//   rubric.json    the configurations to render and the checks made on each
//
// A check compares one number with thresholds for full and partial credit. The number is either
// the student's frame against the built-in solution's frame of the same configuration (`rmse`,
// `covered_rmse`, `max_error`, `bad_pixel_pct`), or one of the lab's error metrics against its
// ground truth (`acne_pct`, `visibility_rmse_area`, `normal_angle_deg`, ...). Lower is better.
// A threshold is a number, or relative to what the solution scores on the same check:
// "solution+0.5", "solution*1.1".
//
// A rubric also lists the mistakes students make, each a small change to the solution with one
// sentence naming the cause and the fix: the grader draws their frames beside the solution's, and
// a student whose frames one of them explains is told that sentence first (grade/diagnosis.h).
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "app/grade/function_probe.h"

namespace shadelab {

struct Threshold {
  double value = 0.0;
  enum class Base { Absolute, SolutionPlus, SolutionTimes } base = Base::Absolute;
  // The bound for a solution that scored `solution` (the value itself when absolute).
  double bound(double solution) const;
  std::string text() const;  // as written: "0.02", "solution+0.5"
};
// "" on success, else what is wrong with `text`.
std::string parseThreshold(const std::string& text, Threshold& out);

enum class Against { Solution, Truth };

struct Check {
  std::string name;    // "no acne"
  std::string metric;  // "rmse" (against the solution) or a lab metric (against the truth)
  Against against = Against::Solution;
  Threshold full, partial;  // value <= full: all points; <= partial: partialCredit of them
  double points = 1.0;      // 0: a condition, earning nothing, that other checks "require"
  bool isCondition() const { return points == 0.0; }
  double partialCredit = 0.5;
  std::string hint;  // shown when the check is not passed in full: what is likely wrong
  // The evidence the hint's cause needs: checks that must have passed in full, or failed, for it to
  // be shown ("check" in the same configuration, "configuration: check" in another). A hint whose
  // evidence is missing stays silent rather than guessing.
  std::vector<std::string> hintIfPassed, hintIfFailed;
  // Another check of the same configuration that must not fail for this one to score: "no acne"
  // means nothing in a frame with no shadow at all.
  std::string requiredCheck;
};

// One frame the checks look at: a scene, a camera and the lab's parameters.
struct Configuration {
  std::string name;
  std::string scene;                                          // "" = the lab's default
  std::string camera;                                         // OrbitCamera::parse text, "" = framed
  std::vector<std::pair<std::string, std::string>> settings;  // lab param -> value, in order
  std::vector<Check> checks;
  // The range the view's values lie in when the frame is right ("range": [0, 1] for visibility):
  // values outside it, an umbra that does not reach its low end and a lit region that does not
  // reach its high end are then measured. Unbounded (shaded colour, say) when absent.
  bool bounded = false;
  float low = 0.0f, high = 1.0f;
  // What the view's three channels hold, as a diagnosis names them ("the normal's x, y, z");
  // "red, green, blue" when the rubric does not say.
  std::string channels = "red, green, blue";
  // The view draws the exercised function's result itself, one evaluation per pixel ("probe":
  // true): the visibility a shadow test returns, the normal a normal map gives. A relation found
  // here speaks of the function, not only of a picture made from it.
  bool probe = false;
  // The exercised function probed by itself (grade/function_probe.h): this configuration draws
  // Exercise::probes[function]'s table rather than a lab's frame, and has no checks (-1: a frame).
  int function = -1;
  // Who sees the configuration's checks in a gradebook that can hide them (Gradescope): visible,
  // hidden, after_due_date or after_published ("visibility"). Every check is graded and counted.
  std::string visibility = "visible";
  bool hidden() const { return visibility != "visible"; }
  bool needsTruth() const;
};

// The visibilities a configuration may have: visible, hidden, after_due_date, after_published.
bool validVisibility(const std::string& visibility);
// Leaves out the configurations a rubric hides (Configuration::hidden); returns how many.
size_t dropHiddenConfigurations(std::vector<Configuration>& configurations);

// A mistake students make, written as a change to the solution: either the starter's TODO region
// replaced by `body`, or `find` (which must occur exactly once) replaced by `replace` in the lab's
// own file. `diagnosis` names the cause and the fix in a sentence or two. Every exercise also has
// the starter itself as its first mistake (`starter`): a submission that has not changed it.
struct Mistake {
  bool starter = false;   // the starter's files as they are
  std::string name;       // "bias-sign"
  std::string diagnosis;  // the cause: "The bias has the wrong sign: ..."
  std::string fix;        // how to put it right, shown only where the exercise reveals the fix
  std::string file;       // which of the exercise's files it changes (the first by default)
  std::string body;       // the TODO region's replacement, or
  std::string find, replace;
};

struct Exercise {
  std::string id;  // "shadows/pcf"
  std::string lab;
  std::string title;
  // "guided": helpers do the coordinate spaces; "from-scratch": the inputs a real shader has and
  // no helper that does the hard part.
  std::string level = "guided";
  // How much a diagnosis reveals: "cause" (what is wrong, never the formula: the from-scratch
  // default, where the formula is the exercise) or "cause-and-fix" (the guided default).
  std::string reveal = "cause-and-fix";
  std::filesystem::path dir;
  std::vector<std::string> files;  // shader files the student submits, relative to a shader root
  double passMark = 60.0;          // percent
  glm::ivec2 size{320, 240};
  std::vector<Configuration> configurations;
  std::vector<Mistake> mistakes;  // the starter first, then the rubric's in order
  // Right answers written differently from the lab's file (other loop forms, another but equal
  // formula): each must score full marks with no diagnosis, or the rubric is too tight. Their
  // `diagnosis` is empty.
  std::vector<Mistake> correct;
  // The function probed by itself ("probes"): each adds a configuration of its name, after the
  // rubric's, whose frame is the probe's table and which costs no points.
  std::vector<FunctionProbe> probes;
  double totalPoints() const;
};

// Where exercises come from: course folders, in the order given (`--exercises DIR`, repeatable,
// then the folders of $SHADELAB_EXERCISES, separated by ':'), then the built-in exercises/. A
// course folder is laid out as exercises/ is (LAB/NAME/rubric.json, statement.md, starter/); an
// id in an earlier folder hides the same id in a later one, so a course can also replace a
// built-in exercise. Its files are read only inside it, as a student's are.
void setCourseFolders(std::vector<std::filesystem::path> folders);
// One more course folder, ahead of those already there (a course dropped on the window or the
// page); one already among them moves to the front.
void addCourseFolder(const std::filesystem::path& folder);
std::vector<std::filesystem::path> exerciseRoots();
std::filesystem::path builtinExercisesRoot();  // exercises/ in the source tree
// Every exercise id under `root`, sorted ("shading/blinn-phong", ...).
std::vector<std::string> listExercises(const std::filesystem::path& root);
// Every exercise id over exerciseRoots(), sorted, each once.
std::vector<std::string> listExercises();
// Reads root/<id>/rubric.json. "" on success, else one line naming the file and the key.
std::string loadExercise(const std::filesystem::path& root, const std::string& id, Exercise& out);
// The same from the first of exerciseRoots() that holds `id`.
std::string loadExercise(const std::string& id, Exercise& out);
// That root, or an empty path where none holds `id`.
std::filesystem::path exerciseRootOf(const std::string& id);

// Where an exercise's TODO region lies in a starter's text: whole lines, from the start of the
// line holding "TODO(exercise ID): begin" to just past the line holding "...: end" (markers
// included). False for a whole-file starter (no region, or the markers out of order).
struct TodoRegion {
  size_t from = 0, to = 0;
};
bool findTodoRegion(const std::string& text, const std::string& id, TodoRegion& out);

// The lab's own text of one of an exercise's files: the built-in file, or for a part file
// (shader/function_parts.h) the built-in functions its starter gives, as the lab defines them.
std::string labText(const Exercise& ex, const std::string& file);
// The solution's text of the starter's TODO region in the lab's `file`, with the lab's text before
// and after it; false for a whole-file starter, or a lab file the starter's text around its region
// cannot be found in.
bool solutionRegion(const Exercise& ex, const std::string& file, std::string& before, std::string& region,
                    std::string& after);

// The text of the mistake's file: the starter with its TODO region replaced, or the lab's own file
// with `find` replaced. "" on success, else one line naming the rubric's mistake and what is wrong.
std::string mistakeSource(const Exercise& ex, const Mistake& m, std::string& out);
// A shader folder holding the mistake's file alone (the starter: all its files), laid out like
// shaders/, at `dir` (made afresh).
std::string writeMistakeFolder(const Exercise& ex, const Mistake& m, const std::filesystem::path& dir);

}  // namespace shadelab

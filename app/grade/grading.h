// What grading an exercise produced, how a check is scored, and the reports made of it: one line
// per check on the terminal, Markdown and a self-contained HTML page for the student (their image,
// the solution's and a difference for every check not passed in full), JSON for a gradebook.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "app/grade/frame_relations.h"
#include "app/grade/function_probe.h"
#include "app/grade/rubric.h"
#include "app/grade/trace.h"

namespace shadelab {

enum class Grade { Full, Partial, Fail };
const char* gradeName(Grade g);  // "PASS", "PARTIAL", "FAIL"

struct CheckResult {
  Check check;
  double value = 0.0;          // the student's number (NaN when it could not be had)
  double solutionValue = 0.0;  // the built-in solution's on the same check
  double fullBound = 0.0, partialBound = 0.0;
  Grade grade = Grade::Fail;
  double earned = 0.0;
  std::string message;  // why it lost points: the rubric's hint, or what went wrong
};

// Scores `value` against the check's thresholds (a NaN value scores nothing).
CheckResult scoreCheck(const Check& check, double value, double solutionValue);
// Checks whose `requires` failed score nothing, whatever their own value.
void applyRequirements(std::vector<CheckResult>& checks);
// The check could not be measured at all (did not compile, the watchdog, a crash): no points.
CheckResult failedCheck(const Check& check, double solutionValue, const std::string& why);

// How a configuration's student frame ended, and (the first that is not Graded) how an exercise's did.
enum class Outcome { Graded, NotSubmitted, DidNotBuild, TimedOut, Crashed };
// "graded", "not submitted", "did not build", "stopped by the watchdog", "crashed"
const char* outcomeName(Outcome o);

struct ConfigurationResult {
  std::string name;
  Outcome outcome = Outcome::Graded;
  std::string description;             // "scene shadow-test, filter=pcf pcf_size=5"
  std::string visibility = "visible";  // the rubric's, for gradebooks that hide checks
  std::vector<std::string> errors;     // compile errors (file:line:col with the caret), watchdog, crash
  // The evidence a diagnosis rests on (grade/diagnosis.h), when the student's frame was drawn:
  bool drawn = false;
  double distance = 0.0;                   // frameDistance of the student's frame to the solution's
  std::vector<double> mistakeDistances;    // ... to each of the rubric's mistakes' frames, in order
  std::vector<double> mistakeSeparations;  // each mistake's frame to the solution's
  // For two mistakes that both show here, the student's frame to both made together
  // (composeChanges): {i, j, distance}, mistakes numbered as above.
  struct PairDistance {
    size_t a = 0, b = 0;
    double distance = 0.0;
  };
  std::vector<PairDistance> pairDistances;
  std::string nonFiniteText;                                     // "37 NaN pixels in x 12-40, y 30-52" ("" when none)
  size_t nanPixels = 0, infPixels = 0;                           // pixels of the student's frame holding NaN, or Inf
  int edgeShiftX = 0, edgeShiftY = 0;                            // the best-matching shift of the frame, in pixels
  double edgeWidthRatio = 1.0;                                   // its edges' width over the solution's
  double outOfRangePct = 0.0, umbraLevel = 0.0, litLevel = 0.0;  // grade/frame_properties.h
  double outsideMedian = 0.0;                                    // the median value of the pixels out of range
  std::vector<FrameRelation> relations;  // how the student's frame relates to the solution's, best first
  // Settings of the configuration at whose other value the solution draws the student's frame:
  // {key, value ("" = the lab's default), distance}, drawn only when nothing else explains it.
  struct SettingMatch {
    std::string key, value;
    double distance = 0.0;
  };
  std::vector<SettingMatch> settingMatches;
  // The solution's slips that draw differently here (grade/configuration_frames.h: drawSlips), each
  // with its frame's distance from the solution's and the student's frame's distance to it, at the
  // slips' size; `slipBase` the student's to the solution's at that size. `slipsDrawn` is false when
  // the slips were not drawn (the window draws them only when a diagnosis needs them).
  struct Slip {
    int index = -1;
    std::string kind, cause, causeAndFix;
    double separation = 0.0, distance = 0.0;
  };
  bool slipsDrawn = false;
  double slipBase = 0.0;
  std::vector<Slip> slips;
  // A function probe's configuration (grade/function_probe.h): no checks, and what its table says.
  bool function = false;
  std::vector<ProbeFinding> probeFindings;
  // The student's function traced beside the solution's (grade/trace.h), on the probe's table or in
  // the lab's draw (trace.pixel): where their values part, or why there is no trace ("" when it was
  // not asked for); traceTried when it was.
  TraceFinding trace;
  std::string traceUnavailable;
  bool traceTried = false;
  // Image files beside the report ("" when not made).
  std::string studentImage, solutionImage, diffImage;
  std::vector<CheckResult> checks;
};

// "scene shadow-test, camera yaw=30, filter=pcf, pcf_size=5"
std::string describeConfiguration(const Configuration& c);

// Scores a configuration's checks from the two sides' numbers, as grade/configuration_frames.h
// reports them (`student` null when nothing of the student's came back). `why`, when not empty, is
// why nothing the student drew can be scored (the watchdog, a crash): every check then scores 0
// with it; a frame that did not build does the same with its first error. Fills out.checks,
// out.errors, the evidence fields and out.outcome. Returns "" or why the rubric is at fault (a metric
// the lab does not report).
std::string scoreChecks(const Exercise& ex, const Configuration& c, const nlohmann::json& solution,
                        const nlohmann::json& student, std::string why, ConfigurationResult& out);

// The slips' evidence of one configuration: the solution's "slips" (its numbers) and the student's
// distances to them (slipDistances); nothing when either is missing or they do not match.
void addSlipEvidence(const nlohmann::json& solution, const nlohmann::json& distances, ConfigurationResult& out);

// A configuration not graded because a file is missing (`why`: "X is in none of the folders"):
// every check scores 0 with it.
void notSubmitted(const Configuration& c, const std::string& why, ConfigurationResult& out);

struct ExerciseResult {
  std::string id, title, lab;
  std::vector<std::string> missingFiles;  // the submission lacks them: not graded, 0 points
  std::vector<std::string> notes;         // e.g. a file identical to the lab's own
  // Every submitted file is the starter's, as handed out: the TODO region still holds its placeholder.
  bool starterUnchanged = false;
  std::vector<ConfigurationResult> configurations;
  // One cause in a sentence or two (grade/diagnosis.h); empty when every point was earned.
  std::string diagnosis;
  std::string mistake;  // the rubric's mistake that explains the frames, when one does
  // What the diagnosis rests on, for the reports and for measuring the grader: "line:N" (the trace:
  // the line of the exercise's file where the student's values part from the solution's), "mistake:NAME",
  // "mistakes:A+B", "relation:KIND", "where:KEY=VALUE", "starter", "starter-result",
  // "non-finite", "property:NAME", "seen:NAME" (a property whose cause is not known),
  // "probe:KIND:KEY" (what the function's table says: grade/function_probe.h), "only:CONFIGURATION",
  // "evidence" ("" with no diagnosis).
  std::string explanation;
  double earned = 0.0, total = 0.0, passMark = 0.0;
  double percent() const { return total > 0 ? 100.0 * earned / total : 0.0; }
  bool passed() const { return percent() + 1e-9 >= passMark; }
  Outcome outcome() const;  // not submitted, else the first configuration's that is not Graded
};

struct GradeReport {
  std::string command;
  std::string renderer;
  std::vector<std::string> studentDirs;
  std::string date;
  std::vector<ExerciseResult> exercises;
};

// "  pcf-5x5 [scene shadow-test, pcf_size=5]  acne_pct  0.12 <= 0.62 (solution+0.5)  PASS  2/2"
std::string checkLine(const ConfigurationResult& c, const CheckResult& r);
// A build error without the program's name ("shading/phong: f.glsl:3: ..." -> "f.glsl:3: ..."):
// every configuration and program variant compiles the same file, so this says it once.
std::string errorWithoutProgram(const std::string& error);
// The terminal's lines for one configuration: its errors, each once per exercise (`printed` holds
// the ones said already: every configuration and program variant compiles the same file), then
// one checkLine per check with the check's hint under it when it lost points.
std::vector<std::string> configurationLines(const ConfigurationResult& c, std::vector<std::string>& printed);
// "  diagnosis: The bias has the wrong sign ..." (nothing when there is no diagnosis).
std::vector<std::string> diagnosisLines(const ExerciseResult& e);
// "shadows/pcf: 6 / 11 points (54.5%), pass mark 60%: NOT PASSED"
std::string exerciseTotalLine(const ExerciseResult& e);
std::string gradeMarkdown(const GradeReport& report);
// Reads the images named in the report from `dir` and embeds them.
std::string gradeHtml(const GradeReport& report, const std::filesystem::path& dir);
std::string gradeJson(const GradeReport& report);

}  // namespace shadelab

// Grading one student: every configuration of each exercise in its own child under the watchdog
// (grade_render.h), the checks scored, the reports written. `shadelab grade --shaders` is this for
// one folder; `grade --class` runs it once per submission.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "app/cli/options.h"
#include "app/grade/grading.h"
#include "app/grade/solution_cache.h"

namespace shadelab {

struct StudentGrading {
  std::vector<std::filesystem::path> shaderDirs;  // the student's folders, searched before the built-in ones
  std::filesystem::path dir;                      // the report folder (exists, holds logs/)
  std::string backend = "osmesa";
  double watchdog = 20.0;  // seconds the student's frames may take per configuration
  SolutionCache cache;
  std::vector<std::string> notes;  // added to every exercise's notes (e.g. how the zip unpacked)
};

struct CacheCount {
  int fromCache = 0, rendered = 0;
};

// Grades the exercises `ids` and writes report.md, report.html and report.json into g.dir.
// Returns "" or why grading could not go on (a rubric or the built-in solution at fault: not the
// student's doing).
std::string gradeStudent(const std::vector<std::string>& ids, const StudentGrading& g, GradeReport& report,
                         CacheCount& cache);

// Renders (or finds in the cache) the solution side of every configuration of `ids`, once, so that
// submissions graded after it only draw their own frames; with `slips`, the solution's slips too
// (what a failing student's diagnosis would otherwise draw). "" or why it failed.
std::string prepareSolutions(const std::vector<std::string>& ids, const std::string& backend,
                             const SolutionCache& cache, const std::filesystem::path& scratch, CacheCount& count,
                             bool slips = false);

// shadelab grade --prepare: fills the solution cache for the exercises (an autograder image does
// this once, when it is built, so that each submission draws only the student's frames).
int runGradePrepare(const Options& o);

// "shadelab: grade: MESSAGE" on stderr; returns grade's exit code for "could not grade" (2).
int cannotGrade(const std::string& message);
// The report's date: "2026-11-26 07:35", local time.
std::string gradeDate();

// --cache DIR, the default folder, or none with --no-cache.
SolutionCache solutionCacheFor(const Options& o);

// "shadows/pcf" -> "shadows-pcf": file names from ids and configuration names.
std::string gradeSlug(const std::string& s);
// Whether `child` lies inside `parent` (both made canonical as far as they exist).
bool pathInside(const std::filesystem::path& child, const std::filesystem::path& parent);

}  // namespace shadelab

// What a class's grading adds up to: a gradebook (CSV, one row per student and exercise, the
// points of every check) and a class page (self-contained HTML: the scores' spread, how many
// submissions ended in each state, the students per diagnosis, and the checks most often missed with their hints and
// the three submissions that missed each by the most, with their images).
//
// Both are made from the students' report.json files alone, in the order of the students' names,
// so a run split into shards and merged gives the same bytes as one run over the whole class.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

namespace shadelab {

struct ClassCheck {
  std::string configuration, check, metric, result, hint;
  std::string message;  // why it lost points (the hint, a requirement not met, a build error)
  double value = 0.0;   // NaN when it could not be measured (did not build, the watchdog, ...)
  double fullAt = 0.0;  // the bound for full points
  double points = 0.0, maxPoints = 0.0;
  std::string studentImage, diffImage;  // file names in the student's report folder ("" if none)
};

struct ClassRow {
  std::string student, exercise, title, status;  // status: outcomeName()
  double score = 0.0, total = 0.0, percent = 0.0, passMark = 0.0;
  bool passed = false;
  std::string diagnosis, mistake;  // grade/diagnosis.h; empty for full marks
  std::vector<ClassCheck> checks;
};

// The rows of one student's report.json (one per exercise), appended to `rows`. "" or one line
// naming the file and what is wrong with it.
std::string readStudentRows(const std::filesystem::path& reportJson, const std::string& student,
                            std::vector<ClassRow>& rows);

// student, exercise, status, score, total, percent, passed, then one column of points per check
// ("shadows/pcf: 5x5 at 512^2: soft edge"), empty where the row's exercise has no such check.
std::string gradebookCsv(const std::vector<ClassRow>& rows);

// The class page. `studentsDir`/<student>/ holds each student's report and images.
std::string classHtml(const std::vector<ClassRow>& rows, const std::filesystem::path& studentsDir);

// Points or a percentage as reports print them: to two decimals, no trailing zeros ("2.5", "77.78").
std::string formatPoints(double v);

}  // namespace shadelab

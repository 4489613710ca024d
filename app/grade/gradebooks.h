// Grades where courses keep them. A student's report (grading.h's gradeJson) as Gradescope's
// autograder results, Classroom 50's result.json or PrairieLearn's external grader results, and a
// class's rows (class_report.h) as the CSV files that Moodle's and Canvas's gradebooks import.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/grade/class_report.h"

namespace shadelab {

// Gradescope's results.json (gradescope-autograders.readthedocs.io, "Autograder Specifications"):
// one test per check, named "exercise: configuration: check", with its points as score and
// max_score, passed or failed, and in its output the value against its thresholds and the hint
// the grader showed; the submission's output (Markdown) holds each exercise's score, diagnosis and
// notes. A test's visibility is its configuration's in the rubric where that is not "visible",
// else `visibility`: visible, hidden, after_due_date or after_published.
nlohmann::json gradescopeResults(const nlohmann::json& report, const std::string& visibility = "visible");
bool validGradescopeVisibility(const std::string& visibility);

// Classroom 50's result.json (schema classroom50/result/v1, published in foundation50/classroom50's
// schemas/result-v1.schema.json): the submission's identity, which the runner hands the autograder
// in its environment, and one test per check. Its points are whole numbers, so every check's
// points are multiplied by the smallest factor (1, 2, 3, ...) that makes them all whole: 2.5 of 3
// points is 5 of 6.
struct Classroom50Identity {
  std::string classroom, assignment, assignmentType, owner, submission, commit, release, review;
  std::string datetime;  // the graded commit's date, UTC, "YYYY-MM-DDTHH:MM:SSZ"
  std::string gradedAt;  // now, in the same form
  std::string submittedBy;
};
// From CLASSROOM, ASSIGNMENT, ASSIGNMENT_TYPE, OWNER (or USERNAME), SUBMISSION_TAG, COMMIT_URL,
// RELEASE_URL, REVIEW_URL (COMMIT_URL where there is no review), COMMIT_DATE and GITHUB_ACTOR.
// Returns "" or one line naming every variable missing or malformed.
std::string classroom50IdentityFromEnvironment(Classroom50Identity& id);
// The factor that makes every check's points whole (at most 100; rounded past that).
int wholePointScale(const nlohmann::json& report);
nlohmann::json classroom50Result(const nlohmann::json& report, const Classroom50Identity& id);

// PrairieLearn's external grader results (prairielearn.readthedocs.io, "External Grading"):
// "score" in [0, 1], a test per check with "points" and "max_points", the diagnosis as the
// message, and for every configuration that lost points the student's frame, the solution's and
// their difference as PNG data URLs, halved in size until the whole file stays under
// `byteLimit`. A submission with a file missing or a shader that does not compile is
// "gradable": false with the reasons in "format_errors": PrairieLearn then charges no attempt.
// `reportDir` holds the report's images.
nlohmann::json prairieLearnResults(const nlohmann::json& report, const std::filesystem::path& reportDir,
                                   size_t byteLimit = 1000000);

// Moodle's "Import grades: CSV file": a header row, a Username column to map to the user's
// username, then per exercise its points and its feedback (the diagnosis), each mapped to a grade
// item and to "Feedback for" that item at import. A feedback column never comes without its grade
// column beside it (imported alone, Moodle's feedback overwrites the linked grade), and an
// exercise a student has no result for leaves both cells empty.
std::string moodleCsv(const std::vector<ClassRow>& rows);

// Canvas's gradebook import: Student, ID, SIS User ID, SIS Login ID and Section first (the
// submission's folder name as the student and their SIS login, which Canvas matches), then one
// column per exercise, "Points Possible" as the second row; an unknown column name becomes a new
// assignment.
std::string canvasCsv(const std::vector<ClassRow>& rows);

}  // namespace shadelab

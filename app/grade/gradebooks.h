// Grades where courses keep them. A student's report (grading.h's gradeJson) as Gradescope's
// autograder results, Classroom 50's result.json or PrairieLearn's external grader results, and a
// class's rows (class_report.h) as the CSV files that Moodle's and Canvas's gradebooks import.
#pragma once
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/grade/class_report.h"
#include "app/grade/rubric.h"

namespace shadelab {

// Gradescope's results.json (gradescope-autograders.readthedocs.io, "Autograder Specifications"):
// one test per check, named "exercise: configuration: check", with its points as score and
// max_score, passed or failed, and in its output the value against its thresholds and the hint
// the grader showed; the submission's output (Markdown) holds each exercise's score, diagnosis and
// notes. A test's visibility is its configuration's in the rubric where that is not "visible",
// else `visibility`: visible, hidden, after_due_date or after_published. With `reportDir` (the
// report's folder), the first check of each configuration that lost points carries that
// configuration's three pictures: Gradescope shows images only inline, so that test's output is
// HTML (its text, then each picture as a PNG data URL), the pictures halved until all fit in
// `pictureBytes`, and left out from the last configuration where even 32 pixels do not fit.
nlohmann::json gradescopeResults(const nlohmann::json& report, const std::string& visibility = "visible",
                                 const std::filesystem::path& reportDir = {}, size_t pictureBytes = size_t(1) << 20);
bool validGradescopeVisibility(const std::string& visibility);

// Classroom 50's result.json (schema classroom50/result/v1, published in foundation50/classroom50's
// schemas/result-v1.schema.json): the submission's identity, which the runner hands the autograder
// in its environment, and one test per check. Its points are whole numbers, so every check's
// points are multiplied by the smallest factor (1, 2, 3, ...) that makes whole every score the
// rubric can give: a check's points and its partial credit's share of them (3 points at half
// credit: x2, 3 of 6 or 6 of 6). The factor is the rubric's, never what one student earned, so
// every student of an assignment has the same max-score.
struct Classroom50Identity {
  std::string classroom, assignment, assignmentType, owner, submission, commit, release, review;
  std::string datetime;  // the graded commit's date, UTC, "YYYY-MM-DDTHH:MM:SSZ"
  std::string gradedAt;  // now, in the same form
  std::string submittedBy;
};
// From CLASSROOM, ASSIGNMENT, ASSIGNMENT_TYPE, OWNER (or USERNAME), SUBMISSION_TAG, COMMIT_URL,
// RELEASE_URL, REVIEW_URL (COMMIT_URL where there is no review), COMMIT_DATE and GITHUB_ACTOR.
// ASSIGNMENT_TYPE is individual, group or team (the runner's word for a group: written "group").
// Returns "" or one line naming every variable missing or malformed.
std::string classroom50IdentityFromEnvironment(Classroom50Identity& id);
// The factor that makes whole every score the exercises' checks can give (at most 100; rounded
// past that).
int wholePointScale(const std::vector<Exercise>& exercises);
// The same for the exercises a report names, their rubrics read by id (exerciseRoots()); an
// exercise that cannot be read counts its checks' points at the default half credit.
int wholePointScale(const nlohmann::json& report);
// Points x `scale`, or x wholePointScale(report) where no scale is given.
nlohmann::json classroom50Result(const nlohmann::json& report, const Classroom50Identity& id, int scale = 0);

// PrairieLearn's external grader results (prairielearn.readthedocs.io, "External Grading"):
// "score" in [0, 1], a test per check with "points" and "max_points", the diagnosis as the
// message, and for every configuration that lost points the student's frame, the solution's and
// their difference as PNG data URLs, halved in size until the whole file stays under
// `byteLimit` (PrairieLearn's 1 MiB), measured as the file is written (dump(2)). A submission with a file missing or a
// shader that does not compile is "gradable": false with the reasons in "format_errors": PrairieLearn then charges no
// attempt. `reportDir` holds the report's images.
nlohmann::json prairieLearnResults(const nlohmann::json& report, const std::filesystem::path& reportDir,
                                   size_t byteLimit = 1048576);

// How a platform knows the student behind a submission, where the class folder is that
// platform's own download of an assignment (submissions.h's readClassFolder): Moodle's participant
// id, Canvas's user id, and the name the platform gave them. A class of folders named by the
// students has none: the name is the username or login.
struct PlatformIdentity {
  std::string id, person;
};
using PlatformIdentities = std::map<std::string, PlatformIdentity>;  // by the submission's name

// A gradebook file, and the students left out of it. A student without a result for every
// exercise in it (their grading crashed, or they were not graded) is left out, so the platform
// keeps the grade they have: an empty cell would clear it (Moodle's CSV import writes no grade for
// an empty cell; Canvas's takes a blank for a removed score). Each left-out student is named with
// why ("ada: no result for shadows/pcf").
struct GradebookFile {
  std::string text;
  std::vector<std::string> leftOut;
};

// Moodle's "Import grades: CSV file" (the course gradebook): a header row, a Username column to
// map to the user's username, then per exercise its points and its feedback (the diagnosis), each
// mapped to a grade item and to "Feedback for" that item at import. Moodle stops the whole import
// at a username it does not know: name each submission after the student's username.
GradebookFile moodleCsv(const std::vector<ClassRow>& rows);

// Moodle's assignment grading worksheet (the assignment's "Upload grading worksheet", which
// matches a row by its Identifier, "Participant 123": the id Moodle's "Download all submissions"
// puts in every folder's name). Identifier, Full name, Grade (the exercises' points summed),
// Maximum Grade, Last modified (grade) (`gradedAt`, ISO 8601, so a grade a teacher changed later
// is kept unless they tick Moodle's override) and Feedback comments. Moodle skips a row whose
// identifier it does not know, and a grade above the assignment's maximum grade: the teacher sets
// that maximum to the rubrics' total.
GradebookFile moodleWorksheetCsv(const std::vector<ClassRow>& rows, const PlatformIdentities& identities,
                                 const std::string& gradedAt);

// Canvas's gradebook import: Student, ID, SIS User ID, SIS Login ID and Section first, then one
// column per exercise, "Points Possible" as the second row; an unknown column name becomes a new
// assignment. Canvas matches a row by ID (its user id: from the file names of its "Download
// Submissions", where the class folder is that download), else by SIS Login ID (the submission's
// name, where the folders are named by the students); a row it cannot match it asks the teacher about.
GradebookFile canvasCsv(const std::vector<ClassRow>& rows, const PlatformIdentities& identities = {});

}  // namespace shadelab

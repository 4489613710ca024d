// Grades where courses keep them. A student's report (grading.h's gradeJson) as Gradescope's
// autograder results, and a class's rows (class_report.h) as the CSV files that Moodle's and
// Canvas's gradebooks import.
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/grade/class_report.h"

namespace shadelab {

// Gradescope's results.json (gradescope-autograders.readthedocs.io, "Autograder Specifications"):
// one test per check, named "exercise: configuration: check", with its points as score and
// max_score, passed or failed, and in its output the value against its thresholds and the hint
// the grader showed; the submission's output holds each exercise's score, diagnosis and notes.
// `visibility`: visible, hidden, after_due_date or after_published.
nlohmann::json gradescopeResults(const nlohmann::json& report, const std::string& visibility = "visible");
bool validGradescopeVisibility(const std::string& visibility);

// GitHub Classroom's grading reporter (classroom-resources/autograding-grading-reporter) reads one
// runner's results, base64-encoded, from <RUNNER>_RESULTS: {"version", "status": pass | fail,
// "max_score", "tests": [{"name", "status": pass | fail, "score", "message", ...}]}; it adds up
// the tests' scores against max_score and reports the points to the classroom.
// tools/github-classroom/grade.sh encodes this for it.
nlohmann::json classroomResults(const nlohmann::json& report);

// Moodle's "Import grades: CSV file": a header row, a Username column to map to the user's
// username, then per exercise its points and its feedback (the diagnosis), each mapped to a grade
// item and to "Feedback for" that item at import.
std::string moodleCsv(const std::vector<ClassRow>& rows);

// Canvas's gradebook import: Student, ID, SIS User ID, SIS Login ID and Section first (the
// submission's folder name as the student and their SIS login, which Canvas matches), then one
// column per exercise, "Points Possible" as the second row; an unknown column name becomes a new
// assignment.
std::string canvasCsv(const std::vector<ClassRow>& rows);

}  // namespace shadelab

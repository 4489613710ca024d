// The grades in the formats courses import, checked against those formats' published rules:
// Gradescope's autograder results.json, Moodle's CSV grade import and Canvas's gradebook import.
#include <gtest/gtest.h>

#include <regex>
#include <sstream>

#include "app/grade/gradebooks.h"

using namespace shadelab;

namespace {

// A report as gradeJson writes it: one exercise, one check passed, one failed with a hint shown.
nlohmann::json report() {
  return nlohmann::json::parse(R"({
    "exercises": [{
      "id": "shadows/pcf", "title": "The PCF loop", "status": "graded", "score": 2.0, "total": 5.0,
      "percent": 40.0, "pass_mark": 70.0, "passed": false,
      "diagnosis": "The offsets are scaled to texture coordinates, but tapLinear takes texels.",
      "missing_files": [], "notes": ["a note"],
      "checks": [
        {"configuration": "5x5", "check": "no acne", "metric": "acne_pct", "value": 0.1, "full_at": 0.3,
         "partial_at": 1.0, "points": 2.0, "max_points": 2.0, "result": "PASS", "message": "", "errors": []},
        {"configuration": "5x5", "check": "soft edge", "metric": "covered_rmse", "value": 0.04, "full_at": 0.003,
         "partial_at": 0.01, "points": 0.0, "max_points": 3.0, "result": "FAIL",
         "message": "The filtered edge differs from the solution's.", "errors": []}
      ]
    }]
  })");
}

std::vector<std::vector<std::string>> parseCsv(const std::string& text) {
  std::vector<std::vector<std::string>> rows(1, std::vector<std::string>(1));
  bool quoted = false;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (quoted) {
      if (c == '"' && i + 1 < text.size() && text[i + 1] == '"')
        rows.back().back() += '"', ++i;
      else if (c == '"')
        quoted = false;
      else
        rows.back().back() += c;
    } else if (c == '"')
      quoted = true;
    else if (c == ',')
      rows.back().emplace_back();
    else if (c == '\n')
      rows.emplace_back(1);
    else
      rows.back().back() += c;
  }
  if (rows.back().size() == 1 && rows.back()[0].empty()) rows.pop_back();
  return rows;
}

std::vector<ClassRow> classRows() {
  std::vector<ClassRow> rows;
  for (const char* student : {"ada", "grace, the second"}) {
    ClassRow r;
    r.student = student;
    r.exercise = "shadows/pcf";
    r.title = "The PCF loop";
    r.status = "graded";
    r.score = student[0] == 'a' ? 5.0 : 2.5;
    r.total = 5.0;
    r.percent = 100.0 * r.score / r.total;
    r.passMark = 70.0;
    r.diagnosis = student[0] == 'a' ? "" : "The bias has the wrong sign, \"negative\".";
    rows.push_back(r);
  }
  return rows;
}

}  // namespace

// Gradescope: "score" a number, "tests" an array of objects with a name, a score no larger than
// max_score, a status of passed or failed, output text and a visibility of the four it knows.
TEST(Gradebooks, GradescopeResultsFollowTheAutograderSpecification) {
  const nlohmann::json r = gradescopeResults(report(), "after_due_date");
  ASSERT_TRUE(r["score"].is_number());
  EXPECT_DOUBLE_EQ(r["score"].get<double>(), 2.0);
  EXPECT_TRUE(r["output"].is_string());
  EXPECT_NE(r["output"].get<std::string>().find("diagnosis: The offsets"), std::string::npos);
  EXPECT_EQ(r["visibility"], "after_due_date");
  ASSERT_TRUE(r["tests"].is_array());
  ASSERT_EQ(r["tests"].size(), 2u);
  double sum = 0.0;
  for (auto& t : r["tests"]) {
    ASSERT_TRUE(t["name"].is_string());
    ASSERT_TRUE(t["score"].is_number() && t["max_score"].is_number());
    EXPECT_LE(t["score"].get<double>(), t["max_score"].get<double>());
    EXPECT_TRUE(t["status"] == "passed" || t["status"] == "failed");
    EXPECT_TRUE(validGradescopeVisibility(t["visibility"].get<std::string>()));
    sum += t["score"].get<double>();
  }
  EXPECT_DOUBLE_EQ(sum, r["score"].get<double>());
  EXPECT_EQ(r["tests"][1]["status"], "failed");
  EXPECT_EQ(r["tests"][1]["name"], "The PCF loop: 5x5: soft edge");
  EXPECT_NE(r["tests"][1]["output"].get<std::string>().find("The filtered edge differs"), std::string::npos);
  EXPECT_FALSE(validGradescopeVisibility("public"));
}

// Moodle: a header row, a user column to map (Username), a numeric grade or '-' per item, and a
// feedback column per item; every row as long as the header.
TEST(Gradebooks, MoodleCsvIsOneUserPerRowWithAGradeAndFeedbackPerExercise) {
  const auto rows = parseCsv(moodleCsv(classRows()));
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0][0], "Username");
  ASSERT_EQ(rows[0].size(), 3u);
  EXPECT_EQ(rows[0][2].rfind("Feedback: ", 0), 0u);
  for (auto& row : rows) EXPECT_EQ(row.size(), rows[0].size());
  EXPECT_EQ(rows[2][0], "grace, the second");  // a comma inside a name stays in its field
  EXPECT_TRUE(std::regex_match(rows[1][1], std::regex("[0-9]+(\\.[0-9]+)?"))) << rows[1][1];
  EXPECT_NE(rows[2][2].find("\"negative\""), std::string::npos) << rows[2][2];
}

// Canvas: Student, ID, SIS User ID, SIS Login ID, Section first; "Points Possible" as the second
// row; the login column filled, which Canvas matches students by; no new column's name ending in
// "(digits)", which Canvas reads as an existing assignment's id.
TEST(Gradebooks, CanvasCsvHasTheColumnsTheGradebookImportMatchesOn) {
  const auto rows = parseCsv(canvasCsv(classRows()));
  ASSERT_EQ(rows.size(), 4u);
  const std::vector<std::string> first(rows[0].begin(), rows[0].begin() + 5);
  EXPECT_EQ(first, (std::vector<std::string>{"Student", "ID", "SIS User ID", "SIS Login ID", "Section"}));
  EXPECT_EQ(rows[1][0], "    Points Possible");
  EXPECT_EQ(rows[1][5], "5");
  EXPECT_EQ(rows[2][3], "ada");
  EXPECT_EQ(rows[3][0], "grace, the second");
  for (size_t c = 5; c < rows[0].size(); ++c)
    EXPECT_FALSE(std::regex_search(rows[0][c], std::regex("\\([0-9]+\\)$"))) << rows[0][c];
  for (auto& row : rows) EXPECT_EQ(row.size(), rows[0].size());
}

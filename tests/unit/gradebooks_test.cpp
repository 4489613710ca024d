// The grades in the formats courses import, checked against those formats' published rules:
// Gradescope's autograder results.json, Classroom 50's result.json, PrairieLearn's external grader
// results, Moodle's CSV grade import and Canvas's gradebook import. (tests/grade/gradebooks_test.sh
// validates the files of real grading runs against JSON schemas.)
#include <gtest/gtest.h>

#include <regex>
#include <sstream>

#include "app/grade/gradebooks.h"
#include "app/measure/image.h"

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
  EXPECT_NE(r["output"].get<std::string>().find("The offsets are scaled"), std::string::npos);
  EXPECT_EQ(r["output_format"], "md");
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

// A configuration the rubric hides keeps its visibility, whatever the command's default.
TEST(Gradebooks, GradescopeTestsTakeTheRubricsVisibility) {
  nlohmann::json r = report();
  r["exercises"][0]["checks"][1]["visibility"] = "hidden";
  const nlohmann::json out = gradescopeResults(r, "visible");
  EXPECT_EQ(out["tests"][0]["visibility"], "visible");
  EXPECT_EQ(out["tests"][1]["visibility"], "hidden");
}

namespace {

Classroom50Identity identityOf(const char* owner) {
  return {"cg",
          "pcf",
          "individual",
          owner,
          "submit/2026-11-28T10-00-00Z-abc1234",
          "https://x/commit/1",
          "https://x/releases/1",
          "https://x/compare/0...1",
          "2026-11-28T10:00:00Z",
          "2026-11-28T10:01:00Z",
          owner};
}

// The rubric of report(): 2 and 3 points, each at half credit when partial.
std::vector<Exercise> rubricOfReport() {
  Exercise ex;
  ex.id = "shadows/pcf";
  ex.configurations.resize(1);
  for (double points : {2.0, 3.0}) {
    Check c;
    c.points = points;
    c.partialCredit = 0.5;
    ex.configurations[0].checks.push_back(c);
  }
  return {ex};
}

}  // namespace

// Classroom 50's points are whole: the factor is the rubric's (3 points at half credit can score
// 1.5, so x2), and the sums follow.
TEST(Gradebooks, Classroom50ScalesHalfPointsToWholeOnes) {
  nlohmann::json r = report();
  r["exercises"][0]["checks"][1]["points"] = 1.5;
  const int scale = wholePointScale(rubricOfReport());
  EXPECT_EQ(scale, 2);
  const nlohmann::json c = classroom50Result(r, identityOf("ada"), scale);
  EXPECT_EQ(c["schema"], "classroom50/result/v1");
  EXPECT_EQ(c["score"], 7);  // (2 + 1.5) x 2
  EXPECT_EQ(c["max-score"], 10);
  ASSERT_EQ(c["tests"].size(), 2u);
  EXPECT_EQ(c["tests"][1]["score"], 3);
  EXPECT_EQ(c["tests"][1]["max-score"], 6);
  EXPECT_TRUE(c["tests"][1]["score"].is_number_integer());
  EXPECT_EQ(c["tests"][1]["passed"], false);
  EXPECT_EQ(c["submitted_by"]["username"], "ada");

  std::vector<Exercise> whole = rubricOfReport();
  for (auto& check : whole[0].configurations[0].checks) check.partialCredit = 0.0;
  EXPECT_EQ(wholePointScale(whole), 1);  // whole points, no partial credit: as they are
  whole[0].configurations[0].checks[0].partialCredit = 0.25;
  EXPECT_EQ(wholePointScale(whole), 2);  // 2 points x 0.25 = 0.5
}

// Two students of one assignment, one with a half-credit check and one with full marks, have the
// same max-score: the factor does not follow what either earned.
TEST(Gradebooks, Classroom50GivesEveryStudentOfAnAssignmentTheSameMaxScore) {
  nlohmann::json partial = report(), full = report();
  partial["exercises"][0]["checks"][1]["points"] = 1.5;
  full["exercises"][0]["checks"][1]["points"] = 3.0;
  full["exercises"][0]["checks"][1]["result"] = "PASS";
  for (auto& r : {&partial, &full}) (*r)["exercises"][0]["id"] = "course/not-an-exercise";  // the report alone
  const nlohmann::json a = classroom50Result(partial, identityOf("ada"));
  const nlohmann::json b = classroom50Result(full, identityOf("grace"));
  EXPECT_EQ(a["max-score"], b["max-score"]);
  EXPECT_EQ(a["max-score"], 10);
  EXPECT_EQ(a["score"], 7);
  EXPECT_EQ(b["score"], 10);
  const nlohmann::json c = classroom50Result(full, identityOf("grace"), wholePointScale(rubricOfReport()));
  EXPECT_EQ(c["max-score"], b["max-score"]);
}

// Outside Classroom 50's runner, every identity variable missing is named in one line.
TEST(Gradebooks, Classroom50NamesTheEnvironmentItLacks) {
  for (const char* name : {"CLASSROOM", "ASSIGNMENT", "ASSIGNMENT_TYPE", "OWNER", "USERNAME", "SUBMISSION_TAG",
                           "COMMIT_URL", "RELEASE_URL", "REVIEW_URL", "COMMIT_DATE"})
    unsetenv(name);
  setenv("CLASSROOM", "cg", 1);
  setenv("COMMIT_DATE", "2026-11-28 10:00", 1);
  Classroom50Identity id;
  const std::string e = classroom50IdentityFromEnvironment(id);
  EXPECT_NE(e.find("not set: ASSIGNMENT, ASSIGNMENT_TYPE, OWNER, SUBMISSION_TAG, COMMIT_URL, RELEASE_URL, REVIEW_URL"),
            std::string::npos)
      << e;
  EXPECT_NE(e.find("COMMIT_DATE is '2026-11-28 10:00'"), std::string::npos) << e;
  EXPECT_EQ(e.find('\n'), std::string::npos);
  unsetenv("CLASSROOM");
  unsetenv("COMMIT_DATE");
}

// The runner's "team" is the schema's group; any other type is named with the valid ones.
TEST(Gradebooks, Classroom50TakesATeamAssignmentAsAGroup) {
  const std::pair<const char*, const char*> environment[] = {
      {"CLASSROOM", "cg"},
      {"ASSIGNMENT", "pcf"},
      {"OWNER", "team-7"},
      {"SUBMISSION_TAG", "submit/2026-11-28T10-00-00Z-abc1234"},
      {"COMMIT_URL", "https://x/commit/1"},
      {"RELEASE_URL", "https://x/releases/tag/submit/2026-11-28T10-00-00Z-abc1234"},
      {"COMMIT_DATE", "2026-11-28T10:00:00Z"}};
  for (auto [name, value] : environment) setenv(name, value, 1);
  setenv("ASSIGNMENT_TYPE", "team", 1);
  Classroom50Identity id;
  EXPECT_EQ(classroom50IdentityFromEnvironment(id), "");
  EXPECT_EQ(id.assignmentType, "group");
  setenv("ASSIGNMENT_TYPE", "pair", 1);
  EXPECT_NE(classroom50IdentityFromEnvironment(id).find("ASSIGNMENT_TYPE is 'pair' (valid: individual, group, team)"),
            std::string::npos);
  for (auto [name, value] : environment) unsetenv(name);
  unsetenv("ASSIGNMENT_TYPE");
}

// PrairieLearn: a score in [0, 1], the failing configuration's three pictures inline, halved until
// the file fits its limit; a submission that does not build is not gradable, with the reason.
TEST(Gradebooks, PrairieLearnResultsFitTheirLimitAndSayWhatCannotBeGraded) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "shadelab_prairielearn_test";
  std::filesystem::create_directories(dir);
  ImageF noise;
  noise.size = {256, 256};
  noise.rgba.resize(size_t(256) * 256 * 4);
  unsigned seed = 1;
  for (float& v : noise.rgba) v = float((seed = seed * 1664525u + 1013904223u) >> 24) / 255.0f;  // incompressible
  for (const char* name : {"s.png", "o.png", "d.png"}) ASSERT_EQ(writePng((dir / name).string(), noise), "");
  nlohmann::json r = report();
  r["exercises"][0]["checks"][1]["images"] = {{"student", "s.png"}, {"solution", "o.png"}, {"diff", "d.png"}};

  const nlohmann::json full = prairieLearnResults(r, dir);
  EXPECT_EQ(full["gradable"], true);
  EXPECT_DOUBLE_EQ(full["score"].get<double>(), 0.4);
  ASSERT_EQ(full["tests"].size(), 2u);
  EXPECT_FALSE(full["tests"][0].contains("images"));  // passed: no pictures
  ASSERT_EQ(full["tests"][1]["images"].size(), 3u);
  EXPECT_EQ(full["tests"][1]["images"][0]["url"].get<std::string>().rfind("data:image/png;base64,", 0), 0u);
  const size_t fullSize = full.dump(2).size();  // as the file is written
  EXPECT_LT(fullSize, 1048576u);

  const nlohmann::json small = prairieLearnResults(r, dir, fullSize / 2);  // half the room: smaller pictures
  EXPECT_LE(small.dump(2).size(), fullSize / 2);
  ASSERT_EQ(small["tests"][1]["images"].size(), 3u);
  const nlohmann::json none = prairieLearnResults(r, dir, 4000);  // no room at all: left out, and said
  EXPECT_LE(none.dump(2).size(), 4000u);
  EXPECT_FALSE(none["tests"][1].contains("images"));
  EXPECT_NE(none["message"].get<std::string>().find("left out"), std::string::npos);

  r["exercises"][0]["status"] = "did not build";
  r["exercises"][0]["checks"][1]["errors"] = {"shadows/pcf.glsl:12:5: error: syntax error"};
  const nlohmann::json broken = prairieLearnResults(r, dir);
  EXPECT_EQ(broken["gradable"], false);
  EXPECT_FALSE(broken.contains("score"));
  ASSERT_EQ(broken["format_errors"].size(), 1u);
  EXPECT_EQ(broken["format_errors"][0], "shadows/pcf.glsl:12:5: error: syntax error");
  std::filesystem::remove_all(dir);
}

// Gradescope shows a picture only inline: the failing configuration's first lost check becomes an
// HTML output holding its text (escaped) and the three pictures as data URLs, within their budget;
// without the report's folder, or with no room, the tests stay Markdown and the output says so.
TEST(Gradebooks, GradescopeCarriesTheFailingConfigurationsPicturesInline) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "shadelab_gradescope_test";
  std::filesystem::create_directories(dir);
  ImageF grey;
  grey.size = {64, 64};
  grey.rgba.assign(size_t(64) * 64 * 4, 0.5f);
  for (const char* name : {"s.png", "o.png", "d.png"}) ASSERT_EQ(writePng((dir / name).string(), grey), "");
  nlohmann::json r = report();
  r["exercises"][0]["checks"][1]["images"] = {{"student", "s.png"}, {"solution", "o.png"}, {"diff", "d.png"}};
  r["exercises"][0]["checks"][1]["message"] = "Depths <compared> & kept.";

  const nlohmann::json shown = gradescopeResults(r, "visible", dir);
  EXPECT_EQ(shown["tests"][0]["output_format"], "md");  // passed: no pictures
  const nlohmann::json& lost = shown["tests"][1];
  ASSERT_EQ(lost["output_format"], "html");
  const std::string html = lost["output"];
  size_t images = 0;
  for (size_t at = 0; (at = html.find("<img src=\"data:image/png;base64,", at)) != std::string::npos; ++at) ++images;
  EXPECT_EQ(images, 3u);
  EXPECT_NE(html.find("<p>Depths &lt;compared&gt; &amp; kept.</p>"), std::string::npos) << "the text escaped, not lost";
  EXPECT_EQ(html.find("```"), std::string::npos) << "no Markdown left in the HTML";
  EXPECT_NE(html.find("the solution's"), std::string::npos);

  EXPECT_EQ(gradescopeResults(r)["tests"][1]["output_format"], "md");  // no folder: text only
  const nlohmann::json none = gradescopeResults(r, "visible", dir, 100);
  EXPECT_EQ(none["tests"][1]["output_format"], "md");
  EXPECT_NE(none["output"].get<std::string>().find("left out"), std::string::npos);
  std::filesystem::remove_all(dir);
}

// Moodle: a header row, a user column to map (Username), a numeric grade per item and its
// feedback column right after it; every row as long as the header. A student without a result for
// every exercise is left out and named: an empty cell would clear the grade Moodle has.
TEST(Gradebooks, MoodleCsvIsOneUserPerRowWithAGradeAndFeedbackPerExercise) {
  const GradebookFile file = moodleCsv(classRows());
  EXPECT_TRUE(file.leftOut.empty());
  const auto rows = parseCsv(file.text);
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0][0], "Username");
  ASSERT_EQ(rows[0].size(), 3u);
  EXPECT_EQ(rows[0][2].rfind("Feedback: ", 0), 0u);
  for (auto& row : rows) EXPECT_EQ(row.size(), rows[0].size());
  EXPECT_EQ(rows[2][0], "grace, the second");  // a comma inside a name stays in its field
  EXPECT_TRUE(std::regex_match(rows[1][1], std::regex("[0-9]+(\\.[0-9]+)?"))) << rows[1][1];
  EXPECT_NE(rows[2][2].find("\"negative\""), std::string::npos) << rows[2][2];

  std::vector<ClassRow> more = classRows();
  ClassRow other = more[0];
  other.exercise = "shadows/pcss-blocker";
  other.title = "The blocker search";
  more.push_back(other);  // ada has it, grace does not
  const GradebookFile wider = moodleCsv(more);
  const auto table = parseCsv(wider.text);
  ASSERT_EQ(table[0].size(), 5u);
  for (size_t c = 1; c < table[0].size(); c += 2)
    EXPECT_EQ(table[0][c + 1], "Feedback: " + table[0][c]) << "each feedback column beside its grade column";
  ASSERT_EQ(table.size(), 2u) << "grace has no result for the blocker search: her row would clear it";
  EXPECT_EQ(table[1][0], "ada");
  for (auto& cell : table[1]) EXPECT_NE(cell, "");
  ASSERT_EQ(wider.leftOut.size(), 1u);
  EXPECT_EQ(wider.leftOut[0], "grace, the second: no result for shadows/pcss-blocker");

  more[0].status = "crashed";  // the grader's failure is no result either
  EXPECT_EQ(moodleCsv(more).leftOut.size(), 2u);
  more[0].status = "did not build";  // the student's: it scores what it scores
  EXPECT_EQ(moodleCsv(more).leftOut.size(), 1u);
}

// Moodle's grading worksheet, for a class folder that is Moodle's own download: a row per
// participant ("Participant 123", the id in the download's folder names), the exercises' points
// summed under the maximum, the grading time in a form PHP's strtotime reads, and no row for a
// submission Moodle would not know or a student without a result.
TEST(Gradebooks, MoodleWorksheetMatchesTheDownloadsParticipants) {
  std::vector<ClassRow> rows = classRows();
  rows[0].student = "Ada Lovelace_123";
  const PlatformIdentities ids = {{"Ada Lovelace_123", {"123", "Ada Lovelace"}}};
  const GradebookFile file = moodleWorksheetCsv(rows, ids, "2026-12-02T10:00:00Z");
  const auto table = parseCsv(file.text);
  ASSERT_EQ(table.size(), 2u);
  EXPECT_EQ(table[0], (std::vector<std::string>{"Identifier", "Full name", "Grade", "Maximum Grade",
                                                "Last modified (grade)", "Feedback comments"}));
  EXPECT_EQ(table[1][0], "Participant 123");
  EXPECT_EQ(table[1][1], "Ada Lovelace");
  EXPECT_EQ(table[1][2], "5");
  EXPECT_EQ(table[1][3], "5");
  EXPECT_EQ(table[1][4], "2026-12-02T10:00:00Z");
  ASSERT_EQ(file.leftOut.size(), 1u);
  EXPECT_NE(file.leftOut[0].find("grace, the second: not a folder of Moodle's download"), std::string::npos);
}

// Canvas: Student, ID, SIS User ID, SIS Login ID, Section first; "Points Possible" as the second
// row; the login column filled, which Canvas matches students by; no new column's name ending in
// "(digits)", which Canvas reads as an existing assignment's id.
TEST(Gradebooks, CanvasCsvHasTheColumnsTheGradebookImportMatchesOn) {
  const auto rows = parseCsv(canvasCsv(classRows()).text);
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

// A class folder that is Canvas's own download: the row carries the user id from the file names,
// which Canvas matches before any login.
TEST(Gradebooks, CanvasCsvCarriesTheDownloadsUserIds) {
  std::vector<ClassRow> rows = classRows();
  rows[0].student = "lovelaceada_4567";
  const auto table = parseCsv(canvasCsv(rows, {{"lovelaceada_4567", {"4567", "lovelaceada"}}}).text);
  ASSERT_EQ(table.size(), 4u);
  EXPECT_EQ(table[2][0], "lovelaceada");
  EXPECT_EQ(table[2][1], "4567");
  EXPECT_EQ(table[2][3], "");
  EXPECT_EQ(table[3][3], "grace, the second");  // no identity: the name as the login, as before
}

#include "app/grade/gradebooks.h"

#include <algorithm>

#include "app/util/csv.h"
#include "app/util/format.h"

namespace shadelab {
namespace {

// The exercises in the order the rows first name them, with their titles and totals.
struct Column {
  std::string id, title;
  double total = 0.0;
};
std::vector<Column> exerciseColumns(const std::vector<ClassRow>& rows) {
  std::vector<Column> columns;
  for (auto& r : rows) {
    auto it = std::find_if(columns.begin(), columns.end(), [&](const Column& c) { return c.id == r.exercise; });
    if (it == columns.end())
      columns.push_back({r.exercise, r.title, r.total});
    else
      it->total = std::max(it->total, r.total);
  }
  return columns;
}

std::vector<std::string> studentsOf(const std::vector<ClassRow>& rows) {
  std::vector<std::string> students;
  for (auto& r : rows)
    if (std::find(students.begin(), students.end(), r.student) == students.end()) students.push_back(r.student);
  return students;
}

const ClassRow* rowOf(const std::vector<ClassRow>& rows, const std::string& student, const std::string& exercise) {
  for (auto& r : rows)
    if (r.student == student && r.exercise == exercise) return &r;
  return nullptr;
}

// What a student reads for one exercise: the status where it was not graded, then the diagnosis.
std::string feedbackOf(const ClassRow& r) {
  std::string text = r.status == "graded" ? "" : r.status + ". ";
  text += formatPoints(r.score) + " / " + formatPoints(r.total) + " points (" + formatPoints(r.percent) +
          " %, pass mark " + formatPoints(r.passMark) + " %).";
  if (!r.diagnosis.empty()) text += " " + r.diagnosis;
  return text;
}

}  // namespace

bool validGradescopeVisibility(const std::string& v) {
  return v == "visible" || v == "hidden" || v == "after_due_date" || v == "after_published";
}

nlohmann::json gradescopeResults(const nlohmann::json& report, const std::string& visibility) {
  nlohmann::json tests = nlohmann::json::array();
  std::string output;
  double score = 0.0;
  for (auto& e : report.value("exercises", nlohmann::json::array())) {
    const std::string id = e.value("id", ""), title = e.value("title", id);
    score += e.value("score", 0.0);
    output += title + " (" + id + "): " + formatPoints(e.value("score", 0.0)) + " / " +
              formatPoints(e.value("total", 0.0)) + " points, " + formatPoints(e.value("percent", 0.0)) +
              " % (pass mark " + formatPoints(e.value("pass_mark", 0.0)) + " %), " + e.value("status", "") + "\n";
    if (e.contains("diagnosis")) output += "  diagnosis: " + e["diagnosis"].get<std::string>() + "\n";
    for (auto& f : e.value("missing_files", nlohmann::json::array()))
      output += "  not submitted: " + f.get<std::string>() + "\n";
    for (auto& n : e.value("notes", nlohmann::json::array())) output += "  note: " + n.get<std::string>() + "\n";
    for (auto& c : e.value("checks", nlohmann::json::array())) {
      std::string text = c.value("result", "") + ": " + c.value("metric", "") + " " +
                         (c["value"].is_number() ? formatNumber(c["value"].get<double>()) : std::string("n/a"));
      if (c["full_at"].is_number()) text += ", full marks at <= " + formatNumber(c["full_at"].get<double>());
      if (c["partial_at"].is_number()) text += ", partial at <= " + formatNumber(c["partial_at"].get<double>());
      if (!c.value("message", "").empty()) text += "\n" + c["message"].get<std::string>();
      for (auto& err : c.value("errors", nlohmann::json::array())) text += "\n" + err.get<std::string>();
      tests.push_back({{"name", title + ": " + c.value("configuration", "") + ": " + c.value("check", "")},
                       {"score", c.value("points", 0.0)},
                       {"max_score", c.value("max_points", 0.0)},
                       {"status", c.value("result", "") == "PASS" ? "passed" : "failed"},
                       {"output", text},
                       {"tags", {id}},
                       {"visibility", visibility}});
    }
  }
  return {{"score", score},
          {"output", output},
          {"output_format", "text"},
          {"visibility", visibility},
          {"stdout_visibility", "hidden"},
          {"tests", tests}};
}

nlohmann::json classroomResults(const nlohmann::json& report) {
  nlohmann::json tests = nlohmann::json::array();
  double total = 0.0;
  bool passed = true;
  for (auto& e : report.value("exercises", nlohmann::json::array())) {
    total += e.value("total", 0.0);
    passed &= e.value("passed", false);
    const std::string title = e.value("title", e.value("id", ""));
    const std::string diagnosis = e.value("diagnosis", "");
    for (auto& c : e.value("checks", nlohmann::json::array())) {
      std::string message = c.value("message", "");
      for (auto& err : c.value("errors", nlohmann::json::array())) message += "\n" + err.get<std::string>();
      if (c.value("result", "") != "PASS" && !diagnosis.empty()) message = diagnosis + "\n" + message;
      tests.push_back({{"name", title + ": " + c.value("configuration", "") + ": " + c.value("check", "")},
                       {"status", c.value("result", "") == "PASS" ? "pass" : "fail"},
                       {"score", c.value("points", 0.0)},
                       {"message", message},
                       {"test_code", c.value("metric", "") + " against the " + c.value("against", "solution")},
                       {"filename", ""},
                       {"line_no", 0},
                       {"execution_time", ""}});
    }
  }
  return {{"version", 1}, {"status", passed ? "pass" : "fail"}, {"max_score", total}, {"tests", tests}};
}

std::string moodleCsv(const std::vector<ClassRow>& rows) {
  const std::vector<Column> columns = exerciseColumns(rows);
  std::string csv = "Username";
  for (auto& c : columns)
    csv += "," + csvField(c.title + " (" + c.id + ")") + "," + csvField("Feedback: " + c.title + " (" + c.id + ")");
  csv += "\n";
  for (auto& student : studentsOf(rows)) {
    csv += csvField(student);
    for (auto& c : columns) {
      const ClassRow* r = rowOf(rows, student, c.id);
      csv += "," + (r ? formatPoints(r->score) : std::string("-")) + "," + (r ? csvField(feedbackOf(*r)) : "");
    }
    csv += "\n";
  }
  return csv;
}

std::string canvasCsv(const std::vector<ClassRow>& rows) {
  const std::vector<Column> columns = exerciseColumns(rows);
  std::string csv = "Student,ID,SIS User ID,SIS Login ID,Section";
  // A name ending in "(digits)" would be taken for an existing assignment's id: none here.
  for (auto& c : columns) csv += "," + csvField("ShadeLab: " + c.title + " [" + c.id + "]");
  csv += "\n    Points Possible,,,,";
  for (auto& c : columns) csv += "," + formatPoints(c.total);
  csv += "\n";
  for (auto& student : studentsOf(rows)) {
    csv += csvField(student) + ",,," + csvField(student) + ",";
    for (auto& c : columns) {
      const ClassRow* r = rowOf(rows, student, c.id);
      csv += "," + (r ? formatPoints(r->score) : std::string());
    }
    csv += "\n";
  }
  return csv;
}

}  // namespace shadelab

#include "app/grade/class_report.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>

#include <nlohmann/json.hpp>

#include "app/measure/image.h"
#include "app/measure/report.h"
#include "app/util/csv.h"

namespace shadelab {

namespace fs = std::filesystem;

namespace {

// The statuses in the order the page lists them (outcomeName's words).
const char* const kStatuses[] = {"graded", "did not build", "stopped by the watchdog", "crashed", "not submitted"};

std::string format(const char* fmt, double v) {
  char s[64];
  std::snprintf(s, sizeof s, fmt, v);
  return s;
}

}  // namespace

std::string formatPoints(double v) { return format("%g", std::round(v * 100) / 100); }

namespace {

std::string checkKey(const ClassRow& row, const ClassCheck& c) {
  return row.exercise + ": " + c.configuration + ": " + c.check;
}

// An image name from a report: a plain file name in the student's folder, nothing else.
bool plainName(const std::string& name) {
  return !name.empty() && name.find('/') == std::string::npos && name.find('\\') == std::string::npos && name != "." &&
         name != "..";
}

std::string figure(const fs::path& file, const std::string& caption) {
  ImageF image;
  if (!readImage(file.string(), image).empty())
    return "<figure><figcaption>" + htmlEscape(caption) + " (missing)</figcaption></figure>";
  return "<figure><img src='" + pngDataUri(image) + "' alt='" + htmlEscape(caption) + "'><figcaption>" +
         htmlEscape(caption) + "</figcaption></figure>";
}

// A link to a student's report: the name percent-encoded where a URL needs it.
std::string reportLink(const std::string& student) {
  std::string href = "students/";
  for (unsigned char c : student) {
    if (std::isalnum(c) || c == '-' || c == '_' || c == '.' || c == '~')
      href += char(c);
    else
      href += format("%%%02X", c);
  }
  return "<a href='" + href + "/report.html'>" + htmlEscape(student) + "</a>";
}

// A bar chart of scores in ten bins of 10 % (the last holds 100 %), as inline SVG; the bins that
// lie at or above the pass mark are green.
std::string histogram(const std::vector<double>& percents, double passMark) {
  int bins[10] = {};
  for (double p : percents) ++bins[std::clamp(int(p / 10.0), 0, 9)];
  const int most = std::max(1, *std::max_element(std::begin(bins), std::end(bins)));
  const int w = 420, h = 150, left = 30, bottom = 24, bar = (w - left) / 10;
  std::string svg = "<svg xmlns='http://www.w3.org/2000/svg' width='" + std::to_string(w) + "' height='" +
                    std::to_string(h + 8) + "' role='img' aria-label='scores'>";
  for (int i = 0; i < 10; ++i) {
    const int bh = (h - bottom - 14) * bins[i] / most, x = left + i * bar, y = h - bottom - bh;
    svg += "<rect x='" + std::to_string(x + 2) + "' y='" + std::to_string(y) + "' width='" + std::to_string(bar - 4) +
           "' height='" + std::to_string(bh) + "' fill='" + (i * 10.0 + 1e-9 >= passMark ? "#1a7f37" : "#c05621") +
           "'/>";
    if (bins[i])
      svg += "<text x='" + std::to_string(x + bar / 2) + "' y='" + std::to_string(y - 3) +
             "' font-size='11' text-anchor='middle'>" + std::to_string(bins[i]) + "</text>";
    svg += "<text x='" + std::to_string(x + bar / 2) + "' y='" + std::to_string(h - bottom + 14) +
           "' font-size='10' text-anchor='middle'>" + std::to_string(i * 10) + (i == 9 ? "-100" : "") + "</text>";
  }
  svg += "<line x1='" + std::to_string(left) + "' y1='" + std::to_string(h - bottom) + "' x2='" + std::to_string(w) +
         "' y2='" + std::to_string(h - bottom) + "' stroke='#444'/><text x='" + std::to_string(left) + "' y='" +
         std::to_string(h + 6) + "' font-size='10'>score, % of the points (green: at or above the pass mark, " +
         format("%.0f", passMark) + " %)</text></svg>";
  return svg;
}

}  // namespace

std::string readStudentRows(const fs::path& reportJson, const std::string& student, std::vector<ClassRow>& rows) {
  std::ifstream in(reportJson);
  if (!in) return reportJson.string() + ": cannot be read";
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  if (j.is_discarded() || !j.is_object() || !j.contains("exercises") || !j["exercises"].is_array())
    return reportJson.string() + ": not a grade report (no \"exercises\" list)";
  // Fields read by name; a missing or mistyped one reads as "" or NaN (a const json's operator[]
  // must not be asked for a key it lacks).
  const auto text = [](const nlohmann::json& o, const char* key) {
    const auto it = o.find(key);
    return it != o.end() && it->is_string() ? it->get<std::string>() : std::string();
  };
  const auto number = [](const nlohmann::json& o, const char* key) {
    const auto it = o.find(key);
    return it != o.end() && it->is_number() ? it->get<double>() : std::nan("");
  };
  const auto list = [](const nlohmann::json& o, const char* key) {
    const auto it = o.find(key);
    return it != o.end() && it->is_array() ? *it : nlohmann::json::array();
  };
  try {
    for (auto& e : j["exercises"]) {
      if (!e.is_object()) return reportJson.string() + ": an exercise that is not an object";
      ClassRow row;
      row.student = student;
      for (auto [key, member] : {std::pair{"id", &ClassRow::exercise},
                                 {"title", &ClassRow::title},
                                 {"status", &ClassRow::status},
                                 {"diagnosis", &ClassRow::diagnosis},
                                 {"mistake", &ClassRow::mistake}})
        row.*member = text(e, key);
      for (auto [key, member] : {std::pair{"score", &ClassRow::score},
                                 {"total", &ClassRow::total},
                                 {"percent", &ClassRow::percent},
                                 {"pass_mark", &ClassRow::passMark}})
        row.*member = number(e, key);
      row.passed = e.value("passed", false);
      for (auto& c : list(e, "checks")) {
        if (!c.is_object()) continue;
        ClassCheck check;
        for (auto [key, member] : {std::pair{"configuration", &ClassCheck::configuration},
                                   {"check", &ClassCheck::check},
                                   {"metric", &ClassCheck::metric},
                                   {"result", &ClassCheck::result},
                                   {"hint", &ClassCheck::hint},
                                   {"message", &ClassCheck::message}})
          check.*member = text(c, key);
        for (auto [key, member] : {std::pair{"value", &ClassCheck::value},
                                   {"full_at", &ClassCheck::fullAt},
                                   {"points", &ClassCheck::points},
                                   {"max_points", &ClassCheck::maxPoints}})
          check.*member = number(c, key);
        if (const auto images = c.find("images"); images != c.end() && images->is_object()) {
          check.studentImage = text(*images, "student");
          check.diffImage = text(*images, "diff");
        }
        row.checks.push_back(std::move(check));
      }
      if (row.exercise.empty() || row.status.empty())
        return reportJson.string() + ": an exercise without \"id\" or \"status\"";
      rows.push_back(std::move(row));
    }
  } catch (const nlohmann::json::exception& e) {
    return reportJson.string() + ": " + e.what();
  }
  return {};
}

std::string gradebookCsv(const std::vector<ClassRow>& rows) {
  // Every check once, in the order the rows first name them.
  std::vector<std::string> columns;
  for (auto& row : rows)
    for (auto& c : row.checks)
      if (std::find(columns.begin(), columns.end(), checkKey(row, c)) == columns.end())
        columns.push_back(checkKey(row, c));
  std::string csv = "student,exercise,status,score,total,percent,passed";
  for (auto& c : columns) csv.append(",").append(csvField(c));
  csv += "\n";
  for (auto& row : rows) {
    csv += csvField(row.student) + "," + csvField(row.exercise) + "," + csvField(row.status) + "," +
           formatPoints(row.score) + "," + formatPoints(row.total) + "," + format("%.1f", row.percent) + "," +
           (row.passed ? "yes" : "no");
    for (auto& column : columns) {
      csv += ",";
      for (auto& c : row.checks)
        if (checkKey(row, c) == column) csv += formatPoints(c.points);
    }
    csv += "\n";
  }
  return csv;
}

std::string classHtml(const std::vector<ClassRow>& rows, const fs::path& studentsDir) {
  std::vector<std::string> exercises, students;
  for (auto& r : rows) {
    if (std::find(exercises.begin(), exercises.end(), r.exercise) == exercises.end()) exercises.push_back(r.exercise);
    if (std::find(students.begin(), students.end(), r.student) == students.end()) students.push_back(r.student);
  }
  std::string h =
      "<!doctype html>\n<html><head><meta charset='utf-8'><title>ShadeLab class report</title><style>"
      "body{font-family:sans-serif;max-width:1150px;margin:2em auto;color:#222}"
      "table{border-collapse:collapse;margin:.5em 0}td,th{border:1px solid #ccc;padding:3px 8px;text-align:right}"
      "td:first-child,th:first-child{text-align:left}.no{color:#c00}.yes{color:#1a7f37}"
      "figure{display:inline-block;margin:4px}img{image-rendering:pixelated}figcaption{font-size:85%;text-align:center}"
      ".miss{border-left:3px solid #c05621;padding-left:.8em;margin:1em 0}.hint{color:#444}"
      "td.diag,th.diag{text-align:left}"
      ".who p{margin:.6em 0 .1em}.who img{width:240px}</style></head><body>\n"
      "<h1>ShadeLab class report</h1>\n<p>" +
      std::to_string(students.size()) + " submissions, " + std::to_string(exercises.size()) +
      (exercises.size() == 1 ? " exercise" : " exercises") +
      ". Each student's own report: the links in the last table.</p>\n";

  for (auto& ex : exercises) {
    std::vector<const ClassRow*> of;
    for (auto& r : rows)
      if (r.exercise == ex) of.push_back(&r);
    std::vector<double> percents;
    int passed = 0;
    std::map<std::string, int> statuses;
    for (auto* r : of) {
      percents.push_back(r->percent);
      passed += r->passed;
      ++statuses[r->status];
    }
    std::vector<double> sorted = percents;
    std::sort(sorted.begin(), sorted.end());
    const double median = sorted.empty()      ? 0.0
                          : sorted.size() % 2 ? sorted[sorted.size() / 2]
                                              : 0.5 * (sorted[sorted.size() / 2 - 1] + sorted[sorted.size() / 2]);
    h += "<h2>" + htmlEscape(ex + ": " + of.front()->title) + "</h2>\n<p>Passed: " + std::to_string(passed) + " of " +
         std::to_string(of.size()) + " (pass mark " + format("%.0f", of.front()->passMark) + " %). Median score " +
         format("%.1f", median) + " %.</p>\n" + histogram(percents, of.front()->passMark) +
         "\n<table><tr><th>status</th><th>submissions</th></tr>";
    for (const char* s : kStatuses)
      h += "<tr><td>" + std::string(s) + "</td><td>" + std::to_string(statuses[s]) + "</td></tr>";
    h += "</table>\n";

    // The students per diagnosis, the most common first (a tie: by the first student's name).
    std::vector<std::pair<std::string, std::vector<const ClassRow*>>> diagnoses;
    for (auto* r : of) {
      if (r->diagnosis.empty()) continue;
      auto it = std::find_if(diagnoses.begin(), diagnoses.end(), [&](auto& d) { return d.first == r->diagnosis; });
      if (it == diagnoses.end())
        diagnoses.push_back({r->diagnosis, {r}});
      else
        it->second.push_back(r);
    }
    std::stable_sort(diagnoses.begin(), diagnoses.end(),
                     [](auto& a, auto& b) { return a.second.size() > b.second.size(); });
    if (!diagnoses.empty()) {
      h += "<h3>Diagnoses</h3>\n<table><tr><th>students</th><th class='diag'>diagnosis</th><th "
           "class='diag'>who</th></tr>\n";
      for (auto& [text, who] : diagnoses) {
        std::string names;
        for (size_t i = 0; i < who.size() && i < 8; ++i) names += (i ? ", " : "") + reportLink(who[i]->student);
        if (who.size() > 8) names += ", ...";
        h += "<tr><td>" + std::to_string(who.size()) + (who.size() == 1 ? " student" : " students") +
             "</td><td class='diag'>" + htmlEscape(text) + "</td><td class='diag'>" + names + "</td></tr>\n";
      }
      h += "</table>\n";
    }

    // The checks, most often missed first (a tie: in rubric order).
    struct Missed {
      const ClassCheck* first;
      std::vector<std::pair<const ClassRow*, const ClassCheck*>> misses;
      int unmeasured = 0;
    };
    std::vector<std::string> order;
    std::map<std::string, Missed> missed;
    for (auto* r : of)
      for (auto& c : r->checks) {
        const std::string key = c.configuration + ": " + c.check;
        if (!missed.count(key)) {
          order.push_back(key);
          missed[key].first = &c;
        }
        if (c.result == "PASS") continue;
        if (std::isfinite(c.value))
          missed[key].misses.push_back({r, &c});
        else
          ++missed[key].unmeasured;
      }
    std::stable_sort(order.begin(), order.end(), [&](auto& a, auto& b) {
      return missed[a].misses.size() + missed[a].unmeasured > missed[b].misses.size() + missed[b].unmeasured;
    });
    h += "<h3>Checks most often missed</h3>\n";
    bool any = false;
    for (auto& key : order) {
      Missed& m = missed[key];
      const size_t count = m.misses.size() + m.unmeasured;
      if (count == 0) continue;
      any = true;
      h += "<div class='miss'><b>" + htmlEscape(key) + "</b> (" + htmlEscape(m.first->metric) + "): missed by " +
           std::to_string(count) + " of " + std::to_string(of.size()) +
           (m.unmeasured
                ? ", " + std::to_string(m.unmeasured) + " of them not measured (did not build, stopped or crashed)"
                : "") +
           ".<br><span class='hint'>Hint given: " + htmlEscape(m.first->hint.empty() ? "(none)" : m.first->hint) +
           "</span>";
      // The three measured misses that lost the most points and, among those, lie farthest past the
      // bound for full points (a tie: by name, the order the rows come in).
      std::stable_sort(m.misses.begin(), m.misses.end(), [](auto& a, auto& b) {
        const double lostA = a.second->maxPoints - a.second->points, lostB = b.second->maxPoints - b.second->points;
        if (lostA != lostB) return lostA > lostB;
        return a.second->value - a.second->fullAt > b.second->value - b.second->fullAt;
      });
      if (!m.misses.empty()) h += "<br>The measured misses farthest from full points:";
      for (size_t i = 0; i < m.misses.size() && i < 3; ++i) {
        const auto& [row, c] = m.misses[i];
        std::string who = reportLink(row->student) + ": " + htmlEscape(c->metric) + " " + format("%.4g", c->value) +
                          ", full points at " + format("%.4g", c->fullAt) + ", " + formatPoints(c->points) + " of " +
                          formatPoints(c->maxPoints) + " points";
        // Within the bound yet not passed: another check it requires failed; the report says which.
        if (c->value <= c->fullAt && !c->message.empty()) who += " (" + htmlEscape(c->message) + ")";
        h += "<div class='who'><p>" + who + "</p>";
        const fs::path folder = studentsDir / row->student;
        if (plainName(c->studentImage)) h += figure(folder / c->studentImage, "their frame");
        if (plainName(c->diffImage)) h += figure(folder / c->diffImage, "difference from the solution, x4");
        h += "</div>";
      }
      h += "</div>\n";
    }
    if (!any) h += "<p>Every submission passed every check in full.</p>\n";
  }

  h += "<h2>Students</h2>\n<table><tr><th>student</th>";
  for (auto& ex : exercises) h += "<th>" + htmlEscape(ex) + "</th>";
  h += "</tr>\n";
  for (auto& s : students) {
    h += "<tr><td>" + reportLink(s) + "</td>";
    for (auto& ex : exercises) {
      const auto r =
          std::find_if(rows.begin(), rows.end(), [&](auto& row) { return row.student == s && row.exercise == ex; });
      if (r == rows.end()) {
        h += "<td></td>";
        continue;
      }
      h += std::string("<td class='") + (r->passed ? "yes" : "no") + "'>" + formatPoints(r->score) + " / " +
           formatPoints(r->total) + (r->status == "graded" ? "" : " (" + r->status + ")") + "</td>";
    }
    h += "</tr>\n";
  }
  return h + "</table>\n</body></html>\n";
}

}  // namespace shadelab

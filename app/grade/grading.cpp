#include "app/grade/grading.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <nlohmann/json.hpp>

#include "app/measure/image.h"
#include "app/measure/report.h"
#include "app/util/format.h"

namespace shadelab {

const char* outcomeName(Outcome o) {
  switch (o) {
    case Outcome::Graded:
      return "graded";
    case Outcome::NotSubmitted:
      return "not submitted";
    case Outcome::DidNotBuild:
      return "did not build";
    case Outcome::TimedOut:
      return "stopped by the watchdog";
    case Outcome::Crashed:
      return "crashed";
  }
  return "?";
}

Outcome ExerciseResult::outcome() const {
  if (!missingFiles.empty()) return Outcome::NotSubmitted;
  for (auto& c : configurations)
    if (c.outcome != Outcome::Graded) return c.outcome;
  return Outcome::Graded;
}

const char* gradeName(Grade g) {
  switch (g) {
    case Grade::Full:
      return "PASS";
    case Grade::Partial:
      return "PARTIAL";
    default:
      return "FAIL";
  }
}

CheckResult scoreCheck(const Check& check, double value, double solutionValue) {
  CheckResult r;
  r.check = check;
  r.value = value;
  r.solutionValue = solutionValue;
  r.fullBound = check.full.bound(solutionValue);
  r.partialBound = std::max(check.partial.bound(solutionValue), r.fullBound);
  if (!std::isfinite(value)) {
    r.grade = Grade::Fail;
    r.message = check.metric + " is not a number: the frame holds NaN or Inf values";
    return r;
  }
  r.grade = value <= r.fullBound ? Grade::Full : value <= r.partialBound ? Grade::Partial : Grade::Fail;
  r.earned = r.grade == Grade::Full      ? check.points
             : r.grade == Grade::Partial ? check.points * check.partialCredit
                                         : 0.0;
  if (r.grade != Grade::Full) r.message = check.hint;
  return r;
}

void applyRequirements(std::vector<CheckResult>& checks) {
  for (auto& r : checks) {
    if (r.check.requiredCheck.empty()) continue;
    for (auto& other : checks)
      if (other.check.name == r.check.requiredCheck && other.grade == Grade::Fail && r.grade != Grade::Fail) {
        r.grade = Grade::Fail;
        r.earned = 0.0;
        r.message = "counts only when '" + other.check.name + "' does not fail";
      }
  }
}

CheckResult failedCheck(const Check& check, double solutionValue, const std::string& why) {
  CheckResult r = scoreCheck(check, std::nan(""), solutionValue);
  r.message = why;
  return r;
}

namespace {
constexpr const char* kFunctionNote =
    "Your function and the solution's, each evaluated by itself on the same table of inputs: no checks and no "
    "points; what the table shows is in the diagnosis when it speaks of it.";
}  // namespace

std::string describeConfiguration(const Configuration& c) {
  if (c.function >= 0) return "the exercised function alone, on a table of inputs";
  std::string s = "scene " + (c.scene.empty() ? std::string("(the lab's default)") : c.scene);
  if (!c.camera.empty()) s += ", camera " + c.camera;
  for (auto& [k, v] : c.settings) s += ", " + k + "=" + v;
  return s;
}

void notSubmitted(const Configuration& c, const std::string& why, ConfigurationResult& out) {
  out.outcome = Outcome::NotSubmitted;
  for (auto& check : c.checks) out.checks.push_back(failedCheck(check, std::nan(""), "not submitted: " + why));
}

namespace {

double number(const nlohmann::json& values, const std::string& key) {
  return values.is_object() && values.contains(key) && values[key].is_number() ? values[key].get<double>()
                                                                               : std::nan("");
}

}  // namespace

void addSlipEvidence(const nlohmann::json& solution, const nlohmann::json& distances, ConfigurationResult& out) {
  out.slips.clear();
  out.slipsDrawn = false;
  if (!distances.is_object() || !solution.contains("slips") || !solution["slips"].is_array()) return;
  const nlohmann::json& slips = solution["slips"];
  const nlohmann::json& to = distances.value("to", nlohmann::json::array());
  if (!to.is_array() || to.size() != slips.size()) return;
  out.slipsDrawn = true;
  out.slipBase = distances.value("distance", 0.0);
  for (size_t i = 0; i < slips.size(); ++i)
    out.slips.push_back({slips[i].value("index", -1), slips[i].value("kind", ""), slips[i].value("cause", ""),
                         slips[i].value("cause_and_fix", ""), slips[i].value("separation", 0.0),
                         to[i].is_number() ? to[i].get<double>() : 1.0});
}

std::string scoreChecks(const Exercise& ex, const Configuration& c, const nlohmann::json& solution,
                        const nlohmann::json& student, std::string why, ConfigurationResult& out) {
  if (!why.empty()) out.errors.push_back(why);
  if (student.is_object()) {
    for (auto& e : student["errors"]) out.errors.push_back(e.get<std::string>());
    if (!student["errors"].empty()) {
      const std::string first = student["errors"][0].get<std::string>();
      why = "did not build: " + first.substr(0, first.find('\n'));  // the message line, without the caret
      out.outcome = Outcome::DidNotBuild;
    }
  }
  if (student.is_object() && why.empty() && student.contains("distance")) {
    out.drawn = true;
    out.distance = student["distance"].get<double>();
    for (auto& d : student["mistakes"]) out.mistakeDistances.push_back(d.get<double>());
    if (solution.contains("mistakes"))
      for (auto& m : solution["mistakes"]) out.mistakeSeparations.push_back(m["distance"].get<double>());
    const auto& p = student["properties"];
    out.nanPixels = p["nan_pixels"].get<size_t>();
    out.infPixels = p["inf_pixels"].get<size_t>();
    out.nonFiniteText = p["non_finite"].get<std::string>();
    out.edgeShiftX = p["edge_shift"][0].get<int>();
    out.edgeShiftY = p["edge_shift"][1].get<int>();
    out.edgeWidthRatio = p["edge_width_ratio"].get<double>();
    out.outOfRangePct = number(student["vs_solution"], "out_of_range_pct");
    out.outsideMedian = p.value("outside_median", 0.0);
    out.umbraLevel = number(student["vs_solution"], "umbra_level");
    out.litLevel = number(student["vs_solution"], "lit_level");
    if (student.contains("pairs") && student["pairs"].is_array())
      for (auto& q : student["pairs"])
        if (q.is_array() && q.size() == 3)
          out.pairDistances.push_back({q[0].get<size_t>(), q[1].get<size_t>(), q[2].get<double>()});
    if (student.contains("settings") && student["settings"].is_array())
      for (auto& m : student["settings"])
        out.settingMatches.push_back({m.value("key", ""), m.value("value", ""), m.value("distance", 0.0)});
    if (student.contains("relations") && student["relations"].is_array())
      for (auto& r : student["relations"])
        out.relations.push_back({r.value("kind", ""), r.value("a", 1.0), r.value("b", 0.0), r.value("residual", 0.0)});
    if (student.contains("probe") && student["probe"].is_array())
      for (auto& f : student["probe"])
        out.probeFindings.push_back(
            {f.value("kind", ""), f.value("key", ""), f.value("text", ""), f.value("fit", 0.0)});
    addSlipEvidence(solution, student.value("slips", nlohmann::json()), out);
    if (student.contains("trace")) out.trace = traceFindingFromJson(student["trace"]);
    out.traceUnavailable = student.value("trace_unavailable", std::string());
    out.traceTried = student.contains("trace") || student.contains("trace_unavailable");
  }
  out.function = c.function >= 0;
  for (auto& check : c.checks) {
    const bool truth = check.against == Against::Truth;
    const double solutionValue = truth ? number(solution["vs_truth"], check.metric) : 0.0;
    if (truth && !std::isfinite(solutionValue)) {
      std::string reported;
      if (solution.contains("vs_truth"))
        for (auto& [k, v] : solution["vs_truth"].items()) reported += (reported.empty() ? "" : ", ") + k;
      return (ex.dir / "rubric.json").string() + ": check '" + check.name + "': the lab reports no metric '" +
             check.metric + "' (it reports: " + (reported.empty() ? "none" : reported) + ")";
    }
    if (!why.empty()) {
      out.checks.push_back(failedCheck(check, solutionValue, why));
      continue;
    }
    CheckResult r = scoreCheck(check, number(student[truth ? "vs_truth" : "vs_solution"], check.metric), solutionValue);
    if (!out.nonFiniteText.empty() && r.grade != Grade::Full)
      r.message = "The frame holds " + out.nonFiniteText + ". " + r.message;
    out.checks.push_back(std::move(r));
  }
  applyRequirements(out.checks);
  return {};
}

namespace {

std::string points(double v) { return formatSignificant(std::round(v * 100.0) / 100.0); }

std::string value(double v) { return std::isfinite(v) ? formatSignificant(v, 4) : "n/a"; }

std::string bound(const Threshold& t, double b) {
  return t.base == Threshold::Base::Absolute ? value(b) : value(b) + " (" + t.text() + ")";
}

// One row of a configuration's table of checks, in the Markdown and the HTML report alike.
constexpr const char* kCheckColumns[] = {"check",         "metric",     "yours",  "solution",
                                         "full marks at", "partial at", "result", "points"};
std::vector<std::string> checkCells(const CheckResult& r) {
  return {r.check.name,
          r.check.metric + (r.check.against == Against::Truth ? " (vs truth)" : " (vs solution)"),
          value(r.value),
          value(r.solutionValue),
          "<= " + bound(r.check.full, r.fullBound),
          "<= " + bound(r.check.partial, r.partialBound),
          gradeName(r.grade),
          r.check.isCondition() ? "condition" : points(r.earned) + " / " + points(r.check.points)};
}

std::string percent(double p) { return formatFixed(p, 1) + "%"; }

}  // namespace

std::string checkLine(const ConfigurationResult& c, const CheckResult& r) {
  char line[512];
  const std::string what = c.name + ": " + r.check.name;
  const std::string earned = r.check.isCondition() ? "condition" : points(r.earned) + "/" + points(r.check.points);
  std::snprintf(line, sizeof line, "  %-7s %-44s %-16s %9s <= %-24s %s", gradeName(r.grade), what.c_str(),
                r.check.metric.c_str(), value(r.value).c_str(), bound(r.check.full, r.fullBound).c_str(),
                earned.c_str());
  return line;
}

std::string errorWithoutProgram(const std::string& error) {
  const size_t name = error.find(": ");
  return name == std::string::npos ? error : error.substr(name + 2);
}

std::vector<std::string> configurationLines(const ConfigurationResult& c, std::vector<std::string>& printed) {
  std::vector<std::string> out;
  for (auto& err : c.errors) {
    const std::string where = errorWithoutProgram(err);
    if (std::find(printed.begin(), printed.end(), where) != printed.end()) continue;
    printed.push_back(where);
    out.push_back("  " + err);
  }
  for (auto& r : c.checks) {
    out.push_back(checkLine(c, r));
    if (!r.message.empty() && c.errors.empty()) out.push_back("          " + r.message);
  }
  return out;
}

std::vector<std::string> diagnosisLines(const ExerciseResult& e) {
  if (e.diagnosis.empty()) return {};
  return {"  diagnosis: " + e.diagnosis};
}

std::string exerciseTotalLine(const ExerciseResult& e) {
  char line[96];
  std::snprintf(line, sizeof line, " points (%.1f%%), pass mark %.0f%%: ", e.percent(), e.passMark);
  return e.id + ": " + points(e.earned) + " / " + points(e.total) + line + (e.passed() ? "passed" : "NOT PASSED");
}

std::string gradeMarkdown(const GradeReport& report) {
  std::string m = "# ShadeLab grade report\n\n";
  m += "- Command: `" + report.command + "`\n- Shaders graded: ";
  for (size_t i = 0; i < report.studentDirs.size(); ++i) m += (i ? ", `" : "`") + report.studentDirs[i] + "`";
  m += "\n- Renderer: " + report.renderer + "\n- Date: " + report.date + "\n\n";
  m += "| exercise | score | pass mark | result |\n|---|---|---|---|\n";
  for (auto& e : report.exercises)
    m += "| " + e.id + " | " + points(e.earned) + " / " + points(e.total) + " (" + percent(e.percent()) + ") | " +
         percent(e.passMark) + " | " + (e.passed() ? "passed" : "**not passed**") + " |\n";
  for (auto& e : report.exercises) {
    m += "\n## " + e.id + ": " + e.title + "\n\n";
    if (!e.diagnosis.empty()) m += "diagnosis: " + e.diagnosis + "\n\n";
    m += "Score " + points(e.earned) + " / " + points(e.total) + " (" + percent(e.percent()) + "), pass mark " +
         percent(e.passMark) + ".\n\n";
    for (auto& f : e.missingFiles) m += "- **Not submitted**: `" + f + "` is in none of the graded folders.\n";
    for (auto& n : e.notes) m += "- " + n + "\n";
    for (auto& c : e.configurations) {
      if (c.function) {  // a table, not a picture: what it shows is in the diagnosis
        m += "\n### " + c.name + "\n\n" + kFunctionNote + "\n";
        continue;
      }
      m += "\n### " + c.name + "\n\n" + c.description + "\n\n";
      for (auto& err : c.errors) m += "```\n" + err + "\n```\n\n";
      if (!c.nonFiniteText.empty()) m += "The frame holds " + c.nonFiniteText + ".\n\n";
      m += "|";
      for (auto& h : kCheckColumns) m += std::string(" ") + h + " |";
      m += "\n|---|---|---|---|---|---|---|---|\n";
      bool lost = false;
      for (auto& r : c.checks) {
        m += "|";
        for (auto& cell : checkCells(r)) m += " " + cell + " |";
        m += "\n";
        lost |= r.grade != Grade::Full;
      }
      for (auto& r : c.checks)
        if (r.grade != Grade::Full && !r.message.empty()) m += "\n- **" + r.check.name + "**: " + r.message;
      m += "\n";
      if (lost && !c.studentImage.empty())
        m += "\n| yours | solution | difference (x4) |\n|---|---|---|\n| ![](" + c.studentImage + ") | ![](" +
             c.solutionImage + ") | ![](" + c.diffImage + ") |\n";
    }
  }
  return m;
}

std::string gradeHtml(const GradeReport& report, const std::filesystem::path& dir) {
  const auto image = [&](const std::string& name, const std::string& caption) {
    ImageF img;
    if (name.empty() || !readImage((dir / name).string(), img).empty()) return std::string();
    return "<figure><img src='" + pngDataUri(img) + "'><figcaption>" + caption + "</figcaption></figure>";
  };
  std::string h =
      "<!doctype html>\n<html><head><meta charset='utf-8'><title>ShadeLab grade report</title><style>"
      "body{font-family:sans-serif;max-width:1100px;margin:2em auto;color:#222}"
      "table{border-collapse:collapse;margin:.5em 0}td,th{border:1px solid #ccc;padding:3px 8px;text-align:right}"
      "td:first-child,th:first-child{text-align:left}.PASS{color:#1a7f37}.PARTIAL{color:#b35900}.FAIL{color:#c00}"
      "tr.PASS,tr.PARTIAL,tr.FAIL{color:inherit}tr.PASS td:nth-child(7){color:#1a7f37}"
      "tr.PARTIAL td:nth-child(7){color:#b35900}tr.FAIL td:nth-child(7){color:#c00}"
      "pre{background:#f6f6f6;padding:.6em;overflow-x:auto}figure{display:inline-block;margin:4px}"
      "img{image-rendering:pixelated}figcaption{font-size:90%;text-align:center}"
      ".diagnosis{border-left:4px solid #c00;padding:.3em .8em;background:#fff4f4}</style></head><body>\n"
      "<h1>ShadeLab grade report</h1>\n<p>Command: <code>" +
      htmlEscape(report.command) + "</code><br>Renderer: " + htmlEscape(report.renderer) +
      "<br>Date: " + htmlEscape(report.date) +
      "</p>\n<table><tr><th>exercise</th><th>score</th><th>pass mark</th><th>result</th></tr>\n";
  for (auto& e : report.exercises)
    h += "<tr><td>" + htmlEscape(e.id) + "</td><td>" + points(e.earned) + " / " + points(e.total) + " (" +
         percent(e.percent()) + ")</td><td>" + percent(e.passMark) + "</td><td class='" +
         (e.passed() ? "PASS'>passed" : "FAIL'>not passed") + "</td></tr>\n";
  h += "</table>\n";
  for (auto& e : report.exercises) {
    h += "<h2>" + htmlEscape(e.id + ": " + e.title) + "</h2>\n";
    if (!e.diagnosis.empty()) h += "<p class='diagnosis'><b>diagnosis:</b> " + htmlEscape(e.diagnosis) + "</p>\n";
    for (auto& f : e.missingFiles) h += "<p class='FAIL'>Not submitted: <code>" + htmlEscape(f) + "</code></p>\n";
    for (auto& n : e.notes) h += "<p>" + htmlEscape(n) + "</p>\n";
    for (auto& c : e.configurations) {
      if (c.function) {
        h += "<h3>" + htmlEscape(c.name) + "</h3>\n<p>" + htmlEscape(kFunctionNote) + "</p>\n";
        continue;
      }
      h += "<h3>" + htmlEscape(c.name) + "</h3>\n<p>" + htmlEscape(c.description) + "</p>\n";
      for (auto& err : c.errors) h += "<pre>" + htmlEscape(err) + "</pre>\n";
      h += "<table><tr>";
      for (auto& head : kCheckColumns) h += std::string("<th>") + head + "</th>";
      h += "</tr>\n";
      bool lost = false;
      for (auto& r : c.checks) {
        h += "<tr class='" + std::string(gradeName(r.grade)) + "'>";
        for (auto& cell : checkCells(r)) h += "<td>" + htmlEscape(cell) + "</td>";
        h += "</tr>\n";
        lost |= r.grade != Grade::Full;
      }
      h += "</table>\n<ul>";
      for (auto& r : c.checks)
        if (r.grade != Grade::Full && !r.message.empty())
          h += "<li><b>" + htmlEscape(r.check.name) + "</b>: " + htmlEscape(r.message) + "</li>";
      h += "</ul>\n";
      if (lost)
        h += image(c.studentImage, "yours") + image(c.solutionImage, "solution") +
             image(c.diffImage, "difference, amplified 4x") + "\n";
    }
  }
  return h + "</body></html>\n";
}

std::string gradeJson(const GradeReport& report) {
  nlohmann::json j;
  j["command"] = report.command;
  j["renderer"] = report.renderer;
  j["shaders"] = report.studentDirs;
  j["date"] = report.date;
  j["exercises"] = nlohmann::json::array();
  const auto number = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); };
  for (auto& e : report.exercises) {
    nlohmann::json je{{"id", e.id},
                      {"title", e.title},
                      {"lab", e.lab},
                      {"score", e.earned},
                      {"total", e.total},
                      {"percent", e.percent()},
                      {"pass_mark", e.passMark},
                      {"passed", e.passed()},
                      {"status", outcomeName(e.outcome())},
                      {"missing_files", e.missingFiles},
                      {"notes", e.notes},
                      {"checks", nlohmann::json::array()}};
    if (!e.diagnosis.empty()) je["diagnosis"] = e.diagnosis;
    if (!e.mistake.empty()) je["mistake"] = e.mistake;
    if (!e.explanation.empty()) je["explanation"] = e.explanation;
    // How far each drawn frame (a function probe's table too) lies from the solution's: a rubric's
    // mutation test tells an equivalent mutant from one the checks let through.
    je["frames"] = nlohmann::json::array();
    for (auto& c : e.configurations)
      if (c.drawn) {
        nlohmann::json frame{{"configuration", c.name}, {"distance", c.distance}, {"function", c.function}};
        // The trace of the function by itself: where the student's values part from the solution's.
        if (c.trace.found) frame["trace"] = toJson(c.trace);
        if (!c.traceUnavailable.empty()) frame["trace_unavailable"] = c.traceUnavailable;
        je["frames"].push_back(std::move(frame));
      }
    for (auto& c : e.configurations)
      for (auto& r : c.checks)
        je["checks"].push_back(
            {{"configuration", c.name},
             {"check", r.check.name},
             {"metric", r.check.metric},
             {"against", r.check.against == Against::Truth ? "truth" : "solution"},
             {"value", number(r.value)},
             {"solution", number(r.solutionValue)},
             {"full_at", number(r.fullBound)},
             {"partial_at", number(r.partialBound)},
             {"result", gradeName(r.grade)},
             {"points", r.earned},
             {"max_points", r.check.points},
             {"message", r.message},
             {"hint", r.check.hint},
             {"errors", c.errors},
             {"visibility", c.visibility},
             {"images", {{"student", c.studentImage}, {"solution", c.solutionImage}, {"diff", c.diffImage}}}});
    j["exercises"].push_back(std::move(je));
  }
  return j.dump(2) + "\n";
}

}  // namespace shadelab

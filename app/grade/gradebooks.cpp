#include "app/grade/gradebooks.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <set>

#include "app/grade/rubric.h"
#include "app/measure/image.h"
#include "app/measure/report.h"
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

// "Title: configuration: check", the name every gradebook gives a check.
std::string checkName(const nlohmann::json& exercise, const nlohmann::json& check) {
  const std::string title = exercise.value("title", exercise.value("id", ""));
  return title + ": " + check.value("configuration", "") + ": " + check.value("check", "");
}

// "FAIL: covered_rmse 0.0261, full marks at <= 0.004, partial at <= 0.015".
std::string checkOutcome(const nlohmann::json& c) {
  std::string text = c.value("result", "") + ": " + c.value("metric", "") + " " +
                     (c["value"].is_number() ? formatNumber(c["value"].get<double>()) : std::string("n/a"));
  if (c["full_at"].is_number()) text += ", full marks at <= " + formatNumber(c["full_at"].get<double>());
  if (c["partial_at"].is_number()) text += ", partial at <= " + formatNumber(c["partial_at"].get<double>());
  return text;
}

// An exercise's score, status, diagnosis, missing files and notes, in Markdown.
std::string exerciseSummary(const nlohmann::json& e) {
  const std::string id = e.value("id", ""), title = e.value("title", id);
  std::string text = "**" + title + "** (" + id + "): " + formatPoints(e.value("score", 0.0)) + " / " +
                     formatPoints(e.value("total", 0.0)) + " points, " + formatPoints(e.value("percent", 0.0)) +
                     " % (pass mark " + formatPoints(e.value("pass_mark", 0.0)) + " %), " + e.value("status", "") +
                     "\n\n";
  if (e.contains("diagnosis")) text += e["diagnosis"].get<std::string>() + "\n\n";
  for (auto& f : e.value("missing_files", nlohmann::json::array()))
    text += "- not submitted: `" + f.get<std::string>() + "`\n";
  for (auto& n : e.value("notes", nlohmann::json::array())) text += "- note: " + n.get<std::string>() + "\n";
  return text;
}

// The pictures of a configuration that lost points, shown with one test of a platform's results
// (its first check not passed in full): the student's frame, the solution's, their difference.
struct Pictures {
  size_t test;
  std::string configuration;
  std::vector<std::pair<std::string, std::string>> files;  // label, file in the report's folder
};

// Adds the pictures of `c`'s configuration for test `test`, the first time a check of it lost points.
void collectPictures(const nlohmann::json& c, size_t test, std::set<std::string>& seen, std::vector<Pictures>& out) {
  const std::string configuration = c.value("configuration", "");
  const auto images = c.value("images", nlohmann::json::object());
  if (c.value("result", "") == "PASS" || !seen.insert(configuration).second) return;
  Pictures p{test, configuration, {}};
  for (auto [key, label] : {std::pair<const char*, const char*>{"student", "your frame"},
                            {"solution", "the solution's"},
                            {"diff", "the difference, amplified"}})
    if (images.value(key, "") != "") p.files.emplace_back(configuration + ": " + label, images.value(key, ""));
  if (!p.files.empty()) out.push_back(std::move(p));
}

// The pictures as PNG data URLs ({label, url} per picture, a list per entry of `pictures`), at full
// size, then halved until all fit in `budget` bytes as they are written in a file indented by two;
// where they still do not fit at 32 pixels, the last configuration is left out and the rest tried
// at full size again. Returns the lists kept (the first `kept` of `pictures`).
std::vector<nlohmann::json> fitPictures(const std::vector<Pictures>& pictures, const std::filesystem::path& reportDir,
                                        size_t budget) {
  std::vector<std::vector<std::pair<std::string, ImageF>>> loaded;  // label, image
  for (auto& p : pictures) {
    loaded.emplace_back();
    for (auto& [label, file] : p.files) {
      ImageF image;
      if (readImage((reportDir / file).string(), image).empty()) loaded.back().emplace_back(label, std::move(image));
    }
  }
  size_t kept = pictures.size();
  for (int factor = 1;;) {
    std::vector<nlohmann::json> lists(kept, nlohmann::json::array());
    size_t bytes = 0;
    int smallest = 1 << 30;
    for (size_t i = 0; i < kept; ++i)
      for (const auto& [label, image] : loaded[i]) {
        const ImageF small = factor == 1 ? image : downsample(image, factor);
        smallest = std::min({smallest, small.size.x, small.size.y});
        lists[i].push_back({{"label", label}, {"url", pngDataUri(small)}});
        bytes += lists[i].back().dump(2).size() + 16;  // + its indentation inside the test
      }
    if (bytes <= budget || kept == 0) return lists;
    if (smallest > 32) {
      factor *= 2;
    } else {  // one configuration fewer, from full size again
      --kept;
      factor = 1;
    }
  }
}

// "(The pictures of N configurations are left out ...)", or "" when all were kept.
std::string leftOutNote(size_t all, size_t kept) {
  if (kept == all) return {};
  return "\n(The pictures of " + std::to_string(all - kept) +
         " configurations are left out to keep the results within their size limit: the full report has them.)";
}

std::string htmlEscaped(const std::string& text) {
  std::string out;
  for (char ch : text) {
    switch (ch) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += ch;
    }
  }
  return out;
}

}  // namespace

bool validGradescopeVisibility(const std::string& v) { return validVisibility(v); }

nlohmann::json gradescopeResults(const nlohmann::json& report, const std::string& visibility,
                                 const std::filesystem::path& reportDir, size_t pictureBytes) {
  nlohmann::json tests = nlohmann::json::array();
  std::string output;
  double score = 0.0;
  std::vector<Pictures> pictures;
  std::vector<std::string> htmls;  // each test's output as HTML
  for (auto& e : report.value("exercises", nlohmann::json::array())) {
    const std::string id = e.value("id", ""), title = e.value("title", id);
    score += e.value("score", 0.0);
    output += exerciseSummary(e);
    std::set<std::string> seen;
    for (auto& c : e.value("checks", nlohmann::json::array())) {
      // The same text in Markdown and, for a test that shows pictures, in HTML.
      std::string text = checkOutcome(c), html = "<p>" + htmlEscaped(checkOutcome(c)) + "</p>";
      if (!c.value("message", "").empty()) {
        text += "\n\n" + c["message"].get<std::string>();
        html += "<p>" + htmlEscaped(c["message"].get<std::string>()) + "</p>";
      }
      for (auto& err : c.value("errors", nlohmann::json::array())) {
        text += "\n\n```\n" + err.get<std::string>() + "\n```";
        html += "<pre>" + htmlEscaped(err.get<std::string>()) + "</pre>";
      }
      htmls.push_back(html);
      const std::string own = c.value("visibility", "visible");
      tests.push_back({{"name", checkName(e, c)},
                       {"score", c.value("points", 0.0)},
                       {"max_score", c.value("max_points", 0.0)},
                       {"status", c.value("result", "") == "PASS" ? "passed" : "failed"},
                       {"output", text},
                       {"output_format", "md"},
                       {"tags", {id}},
                       {"visibility", own != "visible" && validGradescopeVisibility(own) ? own : visibility}});
      if (!reportDir.empty()) collectPictures(c, tests.size() - 1, seen, pictures);
    }
  }
  // Gradescope shows an image only inline, as a data URL in an HTML output (a path is not served),
  // so a test with pictures is written as HTML: its text, then the pictures.
  const std::vector<nlohmann::json> lists = fitPictures(pictures, reportDir, pictureBytes);
  for (size_t i = 0; i < lists.size(); ++i) {
    nlohmann::json& t = tests[pictures[i].test];
    std::string html = htmls[pictures[i].test];
    for (auto& picture : lists[i])
      html += "<figure style=\"display: inline-block; margin: 0 8px 8px 0\"><img src=\"" +
              picture["url"].get<std::string>() + "\" alt=\"" + htmlEscaped(picture["label"]) + "\"><figcaption>" +
              htmlEscaped(picture["label"]) + "</figcaption></figure>";
    t["output"] = html;
    t["output_format"] = "html";
  }
  return {{"score", score},
          {"output", output + leftOutNote(pictures.size(), lists.size())},
          {"output_format", "md"},
          {"test_output_format", "md"},
          {"visibility", visibility},
          {"stdout_visibility", "hidden"},
          {"tests", tests}};
}

namespace {

bool isUtcSecond(const std::string& t) {  // "YYYY-MM-DDTHH:MM:SSZ"
  static const char* shape = "dddd-dd-ddTdd:dd:ddZ";
  if (t.size() != 20) return false;
  for (size_t i = 0; i < t.size(); ++i)
    if (shape[i] == 'd' ? !std::isdigit(static_cast<unsigned char>(t[i])) : t[i] != shape[i]) return false;
  return true;
}

}  // namespace

std::string classroom50IdentityFromEnvironment(Classroom50Identity& id) {
  std::vector<std::string> missing;
  auto read = [&](const char* name, std::string& into, const char* fallback = nullptr) {
    const char* v = std::getenv(name);
    if ((!v || !*v) && fallback) v = std::getenv(fallback);
    if (v && *v)
      into = v;
    else
      missing.push_back(name);
  };
  read("CLASSROOM", id.classroom);
  read("ASSIGNMENT", id.assignment);
  read("ASSIGNMENT_TYPE", id.assignmentType);
  read("OWNER", id.owner, "USERNAME");
  read("SUBMISSION_TAG", id.submission);
  read("COMMIT_URL", id.commit);
  read("RELEASE_URL", id.release);
  read("REVIEW_URL", id.review, "COMMIT_URL");
  read("COMMIT_DATE", id.datetime);
  if (const char* actor = std::getenv("GITHUB_ACTOR")) id.submittedBy = actor;
  id.gradedAt = utcTimeNow("%Y-%m-%dT%H:%M:%SZ");
  std::string problems;
  if (!missing.empty()) {
    problems = "not set: ";
    for (size_t i = 0; i < missing.size(); ++i) problems += (i ? ", " : "") + missing[i];
  }
  auto malformed = [&](const std::string& what) { problems += (problems.empty() ? "" : "; ") + what; };
  // The runner passes "team" for what the result schema calls a group (one repository, several students).
  if (id.assignmentType == "team") id.assignmentType = "group";
  if (!id.assignmentType.empty() && id.assignmentType != "individual" && id.assignmentType != "group")
    malformed("ASSIGNMENT_TYPE is '" + id.assignmentType + "' (valid: individual, group, team)");
  if (!id.submission.empty() && id.submission.rfind("submit/", 0) != 0)
    malformed("SUBMISSION_TAG is '" + id.submission + "' (a submit/... tag)");
  if (!id.datetime.empty() && !isUtcSecond(id.datetime))
    malformed("COMMIT_DATE is '" + id.datetime + "' (the commit's date in UTC, YYYY-MM-DDTHH:MM:SSZ)");
  return problems.empty() ? "" : "Classroom 50's environment: " + problems;
}

namespace {

// The smallest k in 1..100 that makes every value whole.
int wholeFactor(const std::vector<double>& values) {
  for (int k = 1; k <= 100; ++k)
    if (std::all_of(values.begin(), values.end(), [k](double p) { return std::abs(p * k - std::round(p * k)) < 1e-6; }))
      return k;
  return 100;
}

}  // namespace

int wholePointScale(const std::vector<Exercise>& exercises) {
  std::vector<double> values;  // what a check can score: all its points or its partial credit's share
  for (auto& ex : exercises)
    for (auto& configuration : ex.configurations)
      for (auto& c : configuration.checks) {
        values.push_back(c.points);
        values.push_back(c.points * c.partialCredit);
      }
  return wholeFactor(values);
}

int wholePointScale(const nlohmann::json& report) {
  std::vector<Exercise> exercises;
  for (auto& e : report.value("exercises", nlohmann::json::array())) {
    Exercise ex;
    if (!loadExercise(e.value("id", ""), ex).empty()) {  // its checks as the report has them, at half credit
      ex.configurations.assign(1, Configuration{});
      for (auto& c : e.value("checks", nlohmann::json::array())) {
        Check check;
        check.points = c.value("max_points", 0.0);
        ex.configurations[0].checks.push_back(check);
      }
    }
    exercises.push_back(std::move(ex));
  }
  return wholePointScale(exercises);
}

nlohmann::json classroom50Result(const nlohmann::json& report, const Classroom50Identity& id, int scale) {
  const int k = scale > 0 ? scale : wholePointScale(report);
  nlohmann::json tests = nlohmann::json::array();
  long score = 0, maxScore = 0;
  for (auto& e : report.value("exercises", nlohmann::json::array()))
    for (auto& c : e.value("checks", nlohmann::json::array())) {
      const long earned = std::lround(c.value("points", 0.0) * k), most = std::lround(c.value("max_points", 0.0) * k);
      score += earned;
      maxScore += most;
      std::string message = c.value("message", "");
      for (auto& err : c.value("errors", nlohmann::json::array())) message.append("\n").append(err.get<std::string>());
      tests.push_back({{"test-name", checkName(e, c)},
                       {"passed", c.value("result", "") == "PASS"},
                       {"score", earned},
                       {"max-score", most},
                       {"output", checkOutcome(c)},
                       {"message", message}});
    }
  nlohmann::json result = {{"schema", "classroom50/result/v1"},
                           {"classroom", id.classroom},
                           {"assignment", id.assignment},
                           {"assignment_type", id.assignmentType},
                           {"owner", id.owner},
                           {"submission", id.submission},
                           {"commit", id.commit},
                           {"release", id.release},
                           {"review", id.review},
                           {"datetime", id.datetime},
                           {"graded_at", id.gradedAt},
                           {"score", score},
                           {"max-score", maxScore},
                           {"tests", tests}};
  if (!id.submittedBy.empty()) result["submitted_by"] = {{"username", id.submittedBy}};
  return result;
}

nlohmann::json prairieLearnResults(const nlohmann::json& report, const std::filesystem::path& reportDir,
                                   size_t byteLimit) {
  double earned = 0.0, total = 0.0;
  std::string message, output;
  std::vector<std::string> formatErrors;
  nlohmann::json tests = nlohmann::json::array();
  // The pictures of each configuration that lost points, with its first check not passed in full.
  std::vector<Pictures> pictures;
  for (auto& e : report.value("exercises", nlohmann::json::array())) {
    earned += e.value("score", 0.0);
    total += e.value("total", 0.0);
    output += exerciseSummary(e);
    if (e.contains("diagnosis")) message += (message.empty() ? "" : "\n") + e["diagnosis"].get<std::string>();
    const std::string status = e.value("status", "");
    for (auto& f : e.value("missing_files", nlohmann::json::array()))
      formatErrors.push_back(f.get<std::string>() + " is not in the submission");
    std::set<std::string> seen;
    for (auto& c : e.value("checks", nlohmann::json::array())) {
      if (status == "did not build")
        for (auto& err : c.value("errors", nlohmann::json::array()))
          if (std::find(formatErrors.begin(), formatErrors.end(), err.get<std::string>()) == formatErrors.end())
            formatErrors.push_back(err.get<std::string>());
      tests.push_back({{"name", checkName(e, c)},
                       {"description", c.value("metric", "") + " against the " + c.value("against", "solution")},
                       {"points", c.value("points", 0.0)},
                       {"max_points", c.value("max_points", 0.0)},
                       {"message", c.value("message", "")},
                       {"output", checkOutcome(c)}});
      collectPictures(c, tests.size() - 1, seen, pictures);
    }
  }
  nlohmann::json results = {{"message", message}, {"output", output}};
  if (!formatErrors.empty()) {
    results["gradable"] = false;
    results["format_errors"] = formatErrors;
    return results;
  }
  results["gradable"] = true;
  results["score"] = total > 0.0 ? std::clamp(earned / total, 0.0, 1.0) : 0.0;
  results["tests"] = tests;

  // Measured as the file is written (indented by two), where PrairieLearn counts its bytes.
  const size_t text = results.dump(2).size() + 256;  // + the note's own bytes
  const std::vector<nlohmann::json> lists = fitPictures(pictures, reportDir, byteLimit > text ? byteLimit - text : 0);
  for (size_t i = 0; i < lists.size(); ++i) results["tests"][pictures[i].test]["images"] = lists[i];
  results["message"] = results["message"].get<std::string>() + leftOutNote(pictures.size(), lists.size());
  return results;
}

namespace {

// Whether a row is a result a gradebook may take: the grader reached a verdict (a shader that does
// not build or runs away is the student's, and scores what it scores); a crash is the grader's.
bool isResult(const ClassRow* r) { return r && r->status != "crashed"; }

// "" when `student` has a result for every exercise of `columns`, else why they are left out.
std::string withoutResult(const std::vector<ClassRow>& rows, const std::string& student,
                          const std::vector<Column>& columns) {
  std::vector<std::string> missing;
  for (auto& c : columns)
    if (!isResult(rowOf(rows, student, c.id))) missing.push_back(c.id);
  return missing.empty() ? "" : student + ": no result for " + englishList(missing, "");
}

}  // namespace

GradebookFile moodleCsv(const std::vector<ClassRow>& rows) {
  const std::vector<Column> columns = exerciseColumns(rows);
  GradebookFile file;
  file.text = "Username";
  for (auto& c : columns)
    file.text +=
        "," + csvField(c.title + " (" + c.id + ")") + "," + csvField("Feedback: " + c.title + " (" + c.id + ")");
  file.text += "\n";
  for (auto& student : studentsOf(rows)) {
    if (auto why = withoutResult(rows, student, columns); !why.empty()) {
      file.leftOut.push_back(why);
      continue;
    }
    file.text += csvField(student);
    for (auto& c : columns) {
      const ClassRow& r = *rowOf(rows, student, c.id);
      file.text += "," + formatPoints(r.score) + "," + csvField(feedbackOf(r));
    }
    file.text += "\n";
  }
  return file;
}

GradebookFile moodleWorksheetCsv(const std::vector<ClassRow>& rows, const PlatformIdentities& identities,
                                 const std::string& gradedAt) {
  const std::vector<Column> columns = exerciseColumns(rows);
  double maximum = 0.0;
  for (auto& c : columns) maximum += c.total;
  GradebookFile file;
  file.text = "Identifier,Full name,Grade,Maximum Grade,Last modified (grade),Feedback comments\n";
  for (auto& student : studentsOf(rows)) {
    const auto who = identities.find(student);
    if (who == identities.end() || who->second.id.empty()) {
      file.leftOut.push_back(student + ": not a folder of Moodle's download, so no participant to match");
      continue;
    }
    if (auto why = withoutResult(rows, student, columns); !why.empty()) {
      file.leftOut.push_back(why);
      continue;
    }
    double points = 0.0;
    std::string feedback;
    for (auto& c : columns) {
      const ClassRow& r = *rowOf(rows, student, c.id);
      points += r.score;
      // Moodle keeps imported feedback comments as HTML: each exercise a line of its own, escaped.
      feedback +=
          (feedback.empty() ? "" : "<br>") + htmlEscaped((columns.size() > 1 ? c.title + ": " : "") + feedbackOf(r));
    }
    file.text += csvField("Participant " + who->second.id) + "," + csvField(who->second.person) + "," +
                 formatPoints(points) + "," + formatPoints(maximum) + "," + gradedAt + "," + csvField(feedback) + "\n";
  }
  return file;
}

GradebookFile canvasCsv(const std::vector<ClassRow>& rows, const PlatformIdentities& identities) {
  const std::vector<Column> columns = exerciseColumns(rows);
  GradebookFile file;
  file.text = "Student,ID,SIS User ID,SIS Login ID,Section";
  // A name ending in "(digits)" would be taken for an existing assignment's id: none here.
  for (auto& c : columns) file.text += "," + csvField("ShadeLab: " + c.title + " [" + c.id + "]");
  file.text += "\n    Points Possible,,,,";
  for (auto& c : columns) file.text += "," + formatPoints(c.total);
  file.text += "\n";
  for (auto& student : studentsOf(rows)) {
    if (auto why = withoutResult(rows, student, columns); !why.empty()) {
      file.leftOut.push_back(why);
      continue;
    }
    const auto who = identities.find(student);
    if (who != identities.end() && !who->second.id.empty())
      file.text +=
          csvField(who->second.person.empty() ? student : who->second.person) + "," + csvField(who->second.id) + ",,,";
    else
      file.text += csvField(student) + ",,," + csvField(student) + ",";
    for (auto& c : columns) file.text += "," + formatPoints(rowOf(rows, student, c.id)->score);
    file.text += "\n";
  }
  return file;
}

}  // namespace shadelab

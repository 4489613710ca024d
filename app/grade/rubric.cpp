#include "app/grade/rubric.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>

#include "app/measure/report.h"
#include "app/shader/function_parts.h"
#include "app/shader/preprocessor.h"
#include "app/util/contained_path.h"
#include "app/util/format.h"
#include "app/util/read_file.h"

namespace shadelab {

namespace fs = std::filesystem;

double Threshold::bound(double solution) const {
  switch (base) {
    case Base::SolutionPlus:
      return solution + value;
    case Base::SolutionTimes:
      return solution * value;
    default:
      return value;
  }
}

std::string Threshold::text() const {
  switch (base) {
    case Base::SolutionPlus:
      return "solution+" + formatNumber(value);
    case Base::SolutionTimes:
      return "solution*" + formatNumber(value);
    default:
      return formatNumber(value);
  }
}

std::string parseThreshold(const std::string& text, Threshold& out) {
  std::string number = text;
  out.base = Threshold::Base::Absolute;
  if (text.rfind("solution", 0) == 0) {
    const std::string rest = text.substr(8);
    if (rest.empty() || (rest[0] != '+' && rest[0] != '*'))
      return "'" + text + "' is not a number, 'solution+X' or 'solution*X'";
    out.base = rest[0] == '+' ? Threshold::Base::SolutionPlus : Threshold::Base::SolutionTimes;
    number = rest.substr(1);
  }
  char* end = nullptr;
  out.value = std::strtod(number.c_str(), &end);
  if (number.empty() || *end || !(out.value >= 0.0))
    return "'" + text + "' is not a number >= 0, 'solution+X' or 'solution*X'";
  return {};
}

bool Configuration::needsTruth() const {
  return std::any_of(checks.begin(), checks.end(), [](const Check& c) { return c.against == Against::Truth; });
}

double Exercise::totalPoints() const {
  double sum = 0.0;
  for (auto& c : configurations)
    for (auto& k : c.checks) sum += k.points;
  return sum;
}

namespace {
std::vector<fs::path>& courseFolders() {
  static std::vector<fs::path> folders;
  return folders;
}
}  // namespace

void setCourseFolders(std::vector<fs::path> folders) { courseFolders() = std::move(folders); }

void addCourseFolder(const fs::path& folder) {
  std::vector<fs::path>& folders = courseFolders();
  folders.erase(std::remove(folders.begin(), folders.end(), folder), folders.end());
  folders.insert(folders.begin(), folder);
}

fs::path builtinExercisesRoot() { return fs::path(SHADELAB_SOURCE_DIR) / "exercises"; }

std::vector<fs::path> exerciseRoots() {
  std::vector<fs::path> roots = courseFolders();
  if (const char* env = std::getenv("SHADELAB_EXERCISES"); env && *env) {
    std::string list = env;
    for (size_t at = 0; at <= list.size();) {
      const size_t end = std::min(list.find(':', at), list.size());
      if (end > at) roots.emplace_back(list.substr(at, end - at));
      at = end + 1;
    }
  }
  roots.push_back(builtinExercisesRoot());
  return roots;
}

std::vector<std::string> listExercises() {
  std::vector<std::string> ids;
  for (const fs::path& root : exerciseRoots())
    for (std::string& id : listExercises(root)) ids.push_back(std::move(id));
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  return ids;
}

fs::path exerciseRootOf(const std::string& id) {
  std::error_code ec;
  if (id.find("..") == std::string::npos)
    for (const fs::path& root : exerciseRoots())
      if (fs::is_regular_file(root / id / "rubric.json", ec)) return root;
  return {};
}

std::string loadExercise(const std::string& id, Exercise& out) {
  if (const fs::path root = exerciseRootOf(id); !root.empty()) return loadExercise(root, id, out);
  std::string valid;
  for (auto& e : listExercises()) valid += (valid.empty() ? "" : ", ") + e;
  return "unknown exercise '" + id + "' (valid: " + (valid.empty() ? "none" : valid) + ")";
}

std::vector<std::string> listExercises(const fs::path& root) {
  std::vector<std::string> ids;
  std::error_code ec;
  for (auto& lab : fs::directory_iterator(root, ec))
    for (auto& ex : fs::directory_iterator(lab.path(), ec))
      if (fs::is_regular_file(ex.path() / "rubric.json"))
        ids.push_back(lab.path().filename().string() + "/" + ex.path().filename().string());
  std::sort(ids.begin(), ids.end());
  return ids;
}

namespace {

// Against the solution's frame: the frames' differences, then the properties of the student's frame
// (grade/frame_properties.h).
const char* kSolutionMetrics[] = {"rmse",           "covered_rmse",     "max_error",   "bad_pixel_pct",
                                  "non_finite_pct", "out_of_range_pct", "umbra_level", "lit_level",
                                  "edge_shift_px",  "edge_width_change"};

// Reads `key` of `j` as text (strings as they are, numbers formatted), or returns false.
bool text(const nlohmann::json& j, const char* key, std::string& out) {
  if (!j.contains(key)) return false;
  const auto& v = j[key];
  if (v.is_string())
    out = v.get<std::string>();
  else if (v.is_number())
    out = formatNumber(v.get<double>());
  else if (v.is_boolean())
    out = v.get<bool>() ? "on" : "off";
  else
    return false;
  return true;
}

std::string loadCheck(const nlohmann::json& j, const std::string& where, Check& c) {
  if (!j.is_object()) return where + ": not an object";
  if (!text(j, "name", c.name) || c.name.empty()) return where + ": \"name\" is missing";
  const std::string at = where + " (" + c.name + ")";
  if (!text(j, "metric", c.metric) || c.metric.empty()) return at + ": \"metric\" is missing";
  std::string against = "solution";
  text(j, "against", against);
  if (against != "solution" && against != "truth")
    return at + ": \"against\" is '" + against + "' (valid: solution, truth)";
  c.against = against == "truth" ? Against::Truth : Against::Solution;
  if (c.against == Against::Solution &&
      std::find(std::begin(kSolutionMetrics), std::end(kSolutionMetrics), c.metric) == std::end(kSolutionMetrics)) {
    std::string valid;
    for (auto* m : kSolutionMetrics) valid += (valid.empty() ? "" : ", ") + std::string(m);
    return at + ": metric '" + c.metric + "' against the solution (valid: " + valid + ")";
  }
  std::string full, partial;
  if (!text(j, "full", full)) return at + ": \"full\" (the threshold for full marks) is missing";
  if (auto e = parseThreshold(full, c.full); !e.empty()) return at + ": \"full\": " + e;
  c.partial = c.full;  // no partial band unless given: all or nothing
  if (text(j, "partial", partial))
    if (auto e = parseThreshold(partial, c.partial); !e.empty()) return at + ": \"partial\": " + e;
  if (j.contains("points")) {
    if (!j["points"].is_number() || !(j["points"].get<double>() >= 0))
      return at + ": \"points\" must be a number >= 0 (0: a condition other checks require)";
    c.points = j["points"].get<double>();
  }
  if (j.contains("partial_credit")) {
    const auto& p = j["partial_credit"];
    if (!p.is_number() || !(p.get<double>() >= 0 && p.get<double>() <= 1))
      return at + ": \"partial_credit\" must be in [0, 1]";
    c.partialCredit = p.get<double>();
  }
  text(j, "hint", c.hint);
  text(j, "requires", c.requiredCheck);
  if (j.contains("hint_when")) {
    const auto& w = j["hint_when"];
    if (!w.is_object()) return at + ": \"hint_when\" must be an object {\"passed\": [...], \"failed\": [...]}";
    for (auto& [key, list] : w.items()) {
      if (key != "passed" && key != "failed") return at + ": \"hint_when\"." + key + " (valid: passed, failed)";
      if (!list.is_array()) return at + ": \"hint_when\"." + key + " must be an array of check names";
      for (auto& name : list) {
        if (!name.is_string() || name.get<std::string>().empty())
          return at + ": \"hint_when\"." + key + " must hold check names (\"check\" or \"configuration: check\")";
        (key == "passed" ? c.hintIfPassed : c.hintIfFailed).push_back(name.get<std::string>());
      }
    }
  }
  return {};
}

std::string loadConfiguration(const nlohmann::json& j, const std::string& where, Configuration& c) {
  if (!j.is_object()) return where + ": not an object";
  if (!text(j, "name", c.name) || c.name.empty()) return where + ": \"name\" is missing";
  const std::string at = where + " (" + c.name + ")";
  text(j, "scene", c.scene);
  text(j, "camera", c.camera);
  if (j.contains("probe")) {
    if (!j["probe"].is_boolean())
      return at + ": \"probe\" must be true or false (the view draws the function's result)";
    c.probe = j["probe"].get<bool>();
  }
  if (j.contains("visibility") && (!text(j, "visibility", c.visibility) || !validVisibility(c.visibility)))
    return at + ": \"visibility\" must be visible, hidden, after_due_date or after_published";
  if (j.contains("channels") && (!text(j, "channels", c.channels) || c.channels.empty()))
    return at + ": \"channels\" must name the view's three channels (\"the normal's x, y, z\")";
  if (j.contains("range")) {
    const auto& r = j["range"];
    if (!r.is_array() || r.size() != 2 || !r[0].is_number() || !r[1].is_number() ||
        !(r[0].get<double>() < r[1].get<double>()))
      return at + ": \"range\" must be [low, high] with low < high (the values a right frame holds)";
    c.bounded = true;
    c.low = r[0].get<float>();
    c.high = r[1].get<float>();
  }
  if (j.contains("set")) {
    if (!j["set"].is_object()) return at + ": \"set\" must be an object of parameter -> value";
    for (auto& [key, value] : j["set"].items()) {
      std::string v;
      if (!text(j["set"], key.c_str(), v)) return at + ": \"set\"." + key + " must be a string, number or boolean";
      c.settings.emplace_back(key, v);
    }
  }
  if (!j.contains("checks") || !j["checks"].is_array() || j["checks"].empty())
    return at + ": \"checks\" must be a non-empty array";
  for (size_t i = 0; i < j["checks"].size(); ++i) {
    Check check;
    if (auto e = loadCheck(j["checks"][i], at + ": checks[" + std::to_string(i) + "]", check); !e.empty()) return e;
    c.checks.push_back(std::move(check));
  }
  for (auto& k : c.checks)
    if (!k.requiredCheck.empty() &&
        std::none_of(c.checks.begin(), c.checks.end(), [&](const Check& o) { return o.name == k.requiredCheck; }))
      return at + ": check '" + k.name + "' requires '" + k.requiredCheck +
             "', which is not a check of this configuration";
  // A check of no points earns nothing by passing: it only makes sense as a condition that other
  // checks of the configuration require (visibility within [0, 1] before its edges count).
  for (auto& k : c.checks)
    if (k.isCondition() &&
        std::none_of(c.checks.begin(), c.checks.end(), [&](const Check& o) { return o.requiredCheck == k.name; }))
      return at + ": check '" + k.name + "' has no points and no check requires it (a condition needs a check that " +
             "\"requires\" it)";
  return {};
}

// "configuration: check" or "check" (in `here`): whether it names a check of the exercise.
bool checkExists(const std::vector<Configuration>& all, const Configuration& here, const std::string& ref) {
  const auto has = [](const Configuration& c, const std::string& name) {
    return std::any_of(c.checks.begin(), c.checks.end(), [&](const Check& k) { return k.name == name; });
  };
  for (auto& c : all)
    if (ref.rfind(c.name + ": ", 0) == 0 && has(c, ref.substr(c.name.size() + 2))) return true;
  return has(here, ref);
}

// A mistake, or (`correct`) a right answer written differently, which has no diagnosis.
std::string loadMistake(const nlohmann::json& j, const std::string& where, const std::vector<std::string>& files,
                        Mistake& m, bool correct = false) {
  if (!j.is_object()) return where + ": not an object";
  if (!text(j, "name", m.name) || m.name.empty()) return where + ": \"name\" is missing";
  const std::string at = where + " (" + m.name + ")";
  if (!correct && (!text(j, "diagnosis", m.diagnosis) || m.diagnosis.empty()))
    return at + ": \"diagnosis\" is missing: one sentence naming the cause (and the fix, or that in \"fix\")";
  if (!correct) text(j, "fix", m.fix);
  m.file = files.front();
  if (text(j, "file", m.file) && std::find(files.begin(), files.end(), m.file) == files.end())
    return at + ": \"file\" '" + m.file + "' is not one of the exercise's \"files\"";
  const bool body = text(j, "body", m.body), find = text(j, "find", m.find), replace = text(j, "replace", m.replace);
  if (body == (find || replace) || find != replace || (find && m.find.empty()))
    return at +
           ": give either \"body\" (the TODO region's replacement) or \"find\" and \"replace\" (in the lab's file)";
  return {};
}

}  // namespace

bool findTodoRegion(const std::string& text, const std::string& id, TodoRegion& out) {
  const std::string marker = "TODO(exercise " + id + "): ";
  const size_t b = text.find(marker + "begin"), e = text.find(marker + "end");
  if (b == std::string::npos || e == std::string::npos || e < b) return false;
  const size_t lineStart = text.rfind('\n', b), lineEnd = text.find('\n', e);
  out.from = lineStart == std::string::npos ? 0 : lineStart + 1;
  out.to = lineEnd == std::string::npos ? text.size() : lineEnd + 1;
  return true;
}

std::string labText(const Exercise& ex, const std::string& file) {
  if (!file.ends_with(kPartSuffix)) return readWholeFile(builtinShaderDir() / file);
  std::vector<std::string> names;
  for (auto& f : findFunctions(readWholeFile(ex.dir / "starter" / file))) names.push_back(f.name);
  return extractPart(readWholeFile(builtinShaderDir() / file.substr(0, file.size() - kPartSuffix.size())), names);
}

bool solutionRegion(const Exercise& ex, const std::string& file, std::string& before, std::string& region,
                    std::string& after) {
  const std::string starter = readWholeFile(ex.dir / "starter" / file), lab = labText(ex, file);
  TodoRegion r;
  if (!findTodoRegion(starter, ex.id, r)) return false;
  // The starter's text around the region is the lab's (exercise check says so), so the lab's
  // region lies between the same text; a part file's own prose first is matched by its last 400
  // characters before the region.
  const std::string head = starter.substr(0, r.from), tail = starter.substr(r.to);
  constexpr size_t kHead = 400;
  const size_t headAt = lab.find(head.substr(head.size() > kHead ? head.size() - kHead : 0));
  if (headAt == std::string::npos || lab.size() < tail.size()) return false;
  const size_t from = headAt + std::min(head.size(), kHead), to = lab.size() - tail.size();
  if (to < from || lab.compare(to, tail.size(), tail) != 0) return false;
  before = lab.substr(0, from);
  region = lab.substr(from, to - from);
  after = tail;
  return true;
}

std::string mistakeSource(const Exercise& ex, const Mistake& m, std::string& out) {
  const std::string at = (ex.dir / "rubric.json").string() + ": mistake '" + m.name + "'";
  if (m.starter) {
    if (!readWholeFile(ex.dir / "starter" / m.file, out)) return (ex.dir / "starter" / m.file).string() + " is missing";
    return {};
  }
  if (m.find.empty()) {
    const std::string starter = readWholeFile(ex.dir / "starter" / m.file);
    TodoRegion r;
    if (!findTodoRegion(starter, ex.id, r))
      return at + ": the starter " + m.file + " has no TODO region (lines holding 'TODO(exercise " + ex.id +
             "): begin' and '...: end')";
    std::string body = m.body;
    if (!body.empty() && body.back() != '\n') body += '\n';
    out = starter.substr(0, r.from) + body + starter.substr(r.to);
    return {};
  }
  std::string text = readWholeFile(builtinShaderDir() / m.file);
  const size_t at1 = text.find(m.find);
  if (at1 == std::string::npos) return at + ": \"find\" does not occur in the lab's " + m.file;
  if (text.find(m.find, at1 + 1) != std::string::npos)
    return at + ": \"find\" occurs more than once in the lab's " + m.file;
  out = text.replace(at1, m.find.size(), m.replace);
  return {};
}

std::string writeMistakeFolder(const Exercise& ex, const Mistake& m, const fs::path& dir) {
  std::error_code ec;
  fs::remove_all(dir, ec);
  for (auto& file : m.starter ? ex.files : std::vector<std::string>{m.file}) {
    Mistake one = m;
    one.file = file;
    std::string source;
    if (auto e = mistakeSource(ex, one, source); !e.empty()) return e;
    if (auto e = writeTextFile((dir / file).string(), source); !e.empty()) return e;
  }
  return {};
}

std::string loadExercise(const fs::path& root, const std::string& id, Exercise& out) {
  const fs::path dir = root / id;
  const fs::path file = dir / "rubric.json";
  std::error_code ec;  // a name too long for the file system is simply not an exercise
  if (id.find("..") != std::string::npos || !fs::is_regular_file(file, ec)) {
    std::string valid;
    for (auto& e : listExercises(root)) valid += (valid.empty() ? "" : ", ") + e;
    return "unknown exercise '" + id + "' (valid: " + (valid.empty() ? "none in " + root.string() : valid) + ")";
  }
  std::ifstream in(file);
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  const std::string where = file.string();
  if (j.is_discarded() || !j.is_object()) return where + ": not valid JSON";
  out = Exercise{};
  out.id = id;
  out.dir = dir;
  if (!text(j, "lab", out.lab)) return where + ": \"lab\" is missing";
  if (!text(j, "title", out.title)) return where + ": \"title\" is missing";
  text(j, "level", out.level);
  if (out.level != "guided" && out.level != "from-scratch")
    return where + ": \"level\" is '" + out.level + "' (valid: guided, from-scratch)";
  out.reveal = out.level == "from-scratch" ? "cause" : "cause-and-fix";
  text(j, "reveal", out.reveal);
  if (out.reveal != "cause" && out.reveal != "cause-and-fix")
    return where + ": \"reveal\" is '" + out.reveal + "' (valid: cause, cause-and-fix)";
  if (!j.contains("files") || !j["files"].is_array() || j["files"].empty())
    return where + ": \"files\" must list the shader files the student submits";
  for (auto& f : j["files"]) {
    // Names that stay inside a shader folder: the grader reads them from the student's folder.
    const fs::path name = f.is_string() ? containedName(f.get<std::string>()) : fs::path();
    if (name.empty() || name.filename().empty())
      return where + ": \"files\" must hold paths relative to a shader folder, without \"..\"";
    out.files.push_back(name.generic_string());
  }
  if (j.contains("pass_mark")) {
    if (!j["pass_mark"].is_number() || j["pass_mark"].get<double>() < 0 || j["pass_mark"].get<double>() > 100)
      return where + ": \"pass_mark\" must be a percentage in [0, 100]";
    out.passMark = j["pass_mark"].get<double>();
  }
  if (j.contains("size")) {
    const auto& s = j["size"];
    if (!s.is_array() || s.size() != 2 || !s[0].is_number_integer() || !s[1].is_number_integer() ||
        s[0].get<int>() < 16 || s[1].get<int>() < 16 || s[0].get<int>() > 4096 || s[1].get<int>() > 4096)
      return where + ": \"size\" must be [width, height] with 16 <= each <= 4096";
    out.size = {s[0].get<int>(), s[1].get<int>()};
  }
  if (!j.contains("configurations") || !j["configurations"].is_array() || j["configurations"].empty())
    return where + ": \"configurations\" must be a non-empty array";
  for (size_t i = 0; i < j["configurations"].size(); ++i) {
    Configuration c;
    if (auto e = loadConfiguration(j["configurations"][i], where + ": configurations[" + std::to_string(i) + "]", c);
        !e.empty())
      return e;
    out.configurations.push_back(std::move(c));
  }
  if (!(out.totalPoints() > 0)) return where + ": no check has points: a score needs at least one";
  for (auto& c : out.configurations)
    for (auto& k : c.checks)
      for (auto* list : {&k.hintIfPassed, &k.hintIfFailed})
        for (auto& ref : *list)
          if (!checkExists(out.configurations, c, ref))
            return where + ": configuration '" + c.name + "': check '" + k.name + "': \"hint_when\" names '" + ref +
                   "', which is no check (\"check\" in the same configuration, or \"configuration: check\")";
  if (j.contains("probes")) {
    if (!j["probes"].is_array()) return where + ": \"probes\" must be an array";
    for (size_t i = 0; i < j["probes"].size(); ++i) {
      FunctionProbe probe;
      if (auto e = parseFunctionProbe(j["probes"][i], where + ": probes[" + std::to_string(i) + "]", probe); !e.empty())
        return e;
      if (std::any_of(out.configurations.begin(), out.configurations.end(),
                      [&](const Configuration& c) { return c.name == probe.name; }))
        return where + ": probes[" + std::to_string(i) + "]: the name '" + probe.name + "' is used twice";
      Configuration c;
      c.name = probe.name;
      c.function = int(out.probes.size());
      out.configurations.push_back(std::move(c));
      out.probes.push_back(std::move(probe));
    }
  }
  Mistake starter;
  starter.starter = true;
  starter.name = "starter";
  starter.file = out.files.front();
  starter.diagnosis =
      "Your frames are the starter's: the TODO region still holds its placeholder, so nothing you "
      "wrote has changed the picture yet.";
  out.mistakes.push_back(std::move(starter));
  if (j.contains("mistakes")) {
    if (!j["mistakes"].is_array()) return where + ": \"mistakes\" must be an array";
    for (size_t i = 0; i < j["mistakes"].size(); ++i) {
      Mistake m;
      if (auto e = loadMistake(j["mistakes"][i], where + ": mistakes[" + std::to_string(i) + "]", out.files, m);
          !e.empty())
        return e;
      if (std::any_of(out.mistakes.begin(), out.mistakes.end(), [&](const Mistake& o) { return o.name == m.name; }))
        return where + ": mistakes[" + std::to_string(i) + "]: the name '" + m.name + "' is used twice";
      std::string source;
      if (auto e = mistakeSource(out, m, source); !e.empty()) return e;
      out.mistakes.push_back(std::move(m));
    }
  }
  if (j.contains("correct")) {
    if (!j["correct"].is_array()) return where + ": \"correct\" must be an array";
    for (size_t i = 0; i < j["correct"].size(); ++i) {
      Mistake m;
      const std::string at = where + ": correct[" + std::to_string(i) + "]";
      if (auto e = loadMistake(j["correct"][i], at, out.files, m, true); !e.empty()) return e;
      if (std::any_of(out.correct.begin(), out.correct.end(), [&](const Mistake& o) { return o.name == m.name; }))
        return at + ": the name '" + m.name + "' is used twice";
      std::string source;
      if (auto e = mistakeSource(out, m, source); !e.empty()) return e;
      out.correct.push_back(std::move(m));
    }
  }
  return {};
}

bool validVisibility(const std::string& v) {
  return v == "visible" || v == "hidden" || v == "after_due_date" || v == "after_published";
}

size_t dropHiddenConfigurations(std::vector<Configuration>& configurations) {
  return std::erase_if(configurations, [](const Configuration& c) { return c.hidden(); });
}

}  // namespace shadelab

// shadelab exercise check [ID | DIR]: an exercise checked before it goes out to students. The
// rubric loads (keys, thresholds, mistakes); the starter is the lab's file outside its TODO
// region; then the solution, the starter, every listed mistake and every correct variant are
// graded as one class (by this program's own `grade --class`, child processes and all), and the
// results must say that the rubric can tell them apart: the solution and each correct variant
// score 100 % with no diagnosis, the starter compiles, draws and scores under 30 %, each mistake
// loses points and is diagnosed as itself, every check fails for the starter or some mistake,
// and every hint is shown to one of them.
//
// With --unlisted DIR, the exercise's set of mistakes no rubric lists (DIR/LAB/NAME.json, each
// after a mistake seen in students' homework) is graded in the same class: how many the grader
// names with their cause, without being told them, is the measure of its diagnoses; one that
// passes or is named wrongly (a cause the submission did not commit) is a problem.
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>

#include <nlohmann/json.hpp>

#include "app/cli/commands.h"
#include "app/grade/frame_properties.h"
#include "app/grade/mutants.h"
#include "app/grade/rubric.h"
#include "app/lab/lab.h"
#include "app/measure/report.h"
#include "app/shader/function_parts.h"
#include "app/shader/preprocessor.h"
#include "app/util/format.h"
#include "app/util/read_file.h"

namespace shadelab {

namespace fs = std::filesystem;

namespace {

constexpr double kStarterBelow = 30.0;  // percent: a starter that scores more gives away the exercise

// The starter equals the lab's file but for its TODO region: "" or where they part.
std::string starterMatchesLabFile(const Exercise& ex, const std::string& file) {
  std::string starter = readWholeFile(ex.dir / "starter" / file);
  const std::string lab = labText(ex, file);
  if (file.ends_with(kPartSuffix)) {  // a part's prose before its first function is the teacher's own
    const std::vector<FunctionSpan> spans = findFunctions(starter);
    size_t at = 0;
    for (int line = 1; !spans.empty() && line < spans.front().firstLine && at != std::string::npos; ++line)
      at = starter.find('\n', at) + 1;
    starter = starter.substr(std::min(at, starter.size()));
  }
  TodoRegion r;
  if (!findTodoRegion(starter, ex.id, r)) return {};  // a whole-file starter: nothing to compare
  const std::string before = starter.substr(0, r.from), after = starter.substr(r.to);
  const auto lineOf = [](const std::string& text, size_t at) {
    return 1 + std::count(text.begin(), text.begin() + std::ptrdiff_t(std::min(at, text.size())), '\n');
  };
  if (lab.compare(0, before.size(), before) != 0) {
    size_t at = 0;
    while (at < before.size() && at < lab.size() && before[at] == lab[at]) ++at;
    return "starter/" + file + " differs from the lab's " + file + " before its TODO region, at line " +
           std::to_string(lineOf(starter, at));
  }
  if (lab.size() < after.size() || lab.compare(lab.size() - after.size(), after.size(), after) != 0)
    return "starter/" + file + " differs from the lab's " + file + " after its TODO region (from line " +
           std::to_string(lineOf(starter, r.to)) + ")";
  return {};
}

// The unlisted mistakes of every exercise checked, for the measure in all.
struct UnlistedTally {
  size_t mistakes = 0, named = 0, wrong = 0, passing = 0;
  size_t tracedElsewhere = 0;  // a trace's line that is not the mistake's (unnamed, its claims true)
};

// How the grader did on an unlisted mistake, worst first.
enum class Verdict { Passes, Wrong, Unnamed, Named };
constexpr const char* kVerdicts[] = {"passes", "wrong", "unnamed", "named"};

// A mistake no rubric lists, the explanations (ExerciseResult::explanation) that name its cause,
// and how the grader did on it when the set was last measured: doing worse is a problem, so the
// measure only moves forward (a better verdict is written into the file by whoever improves it).
struct UnlistedMistake {
  Mistake change;                    // body, or find and replace, as a rubric's mistake
  std::vector<std::string> namedBy;  // "relation:complement", "where:light_type=spot", ...
  std::vector<int> lines;            // the lines of the file that hold the mistake: a trace naming one names it
  Verdict recorded = Verdict::Named;
};

// The lines of `changed` that are not in `base` (a longest common subsequence of their lines,
// whitespace aside): where a mistake written as a whole region lies, when its set does not say.
std::vector<int> changedLines(const std::string& changed, const std::string& base) {
  const auto split = [](const std::string& text) {
    std::vector<std::string> lines;
    size_t at = 0;
    while (at <= text.size()) {
      const size_t end = std::min(text.find('\n', at), text.size());
      std::string line;
      for (size_t i = at; i < end; ++i)
        if (!std::isspace(static_cast<unsigned char>(text[i]))) line += text[i];
      lines.push_back(line);
      at = end + 1;
    }
    return lines;
  };
  const std::vector<std::string> a = split(changed), b = split(base);
  std::vector<std::vector<int>> lcs(a.size() + 1, std::vector<int>(b.size() + 1, 0));
  for (size_t i = a.size(); i-- > 0;)
    for (size_t j = b.size(); j-- > 0;)
      lcs[i][j] = a[i] == b[j] ? lcs[i + 1][j + 1] + 1 : std::max(lcs[i + 1][j], lcs[i][j + 1]);
  std::vector<int> out;
  for (size_t i = 0, j = 0; i < a.size();) {
    if (j < b.size() && a[i] == b[j]) {
      ++i;
      ++j;
    } else if (j < b.size() && lcs[i][j + 1] >= lcs[i + 1][j]) {
      ++j;
    } else {
      if (!a[i].empty()) out.push_back(int(i) + 1);
      ++i;
    }
  }
  return out;
}

// DIR/LAB/NAME.json: {"mistakes": [{"name", "after", "body" | "find" + "replace", "named_by": [...],
// "today": "named" | "unnamed" | "wrong" | "passes"}]}.
// Nothing when the exercise has no set; "" or one line naming the file and the key.
std::string loadUnlisted(const Exercise& ex, const fs::path& dir, std::vector<UnlistedMistake>& out) {
  const fs::path file = dir / (ex.id + ".json");
  std::error_code ec;
  if (dir.empty() || !fs::is_regular_file(file, ec)) return {};
  const nlohmann::json j = nlohmann::json::parse(readWholeFile(file), nullptr, false);
  const std::string at = file.string();
  if (!j.is_object() || !j.contains("mistakes") || !j["mistakes"].is_array())
    return at + ": must be an object with \"mistakes\": [...]";
  for (auto& m : j["mistakes"]) {
    UnlistedMistake u;
    if (!m.is_object() || !m.contains("name") || !m["name"].is_string() || !m.contains("named_by") ||
        !m["named_by"].is_array())
      return at + ": every mistake needs \"name\" and \"named_by\" (the explanations that name its cause)";
    u.change.name = m["name"].get<std::string>();
    u.change.file = m.value("file", ex.files.front());
    u.change.body = m.value("body", "");
    u.change.find = m.value("find", "");
    u.change.replace = m.value("replace", "");
    for (auto& n : m["named_by"])
      if (n.is_string()) u.namedBy.push_back(n.get<std::string>());
    const std::string today = m.value("today", "");
    const auto it = std::find(std::begin(kVerdicts), std::end(kVerdicts), today);
    if (it == std::end(kVerdicts))
      return at + ": " + u.change.name + ": \"today\" is '" + today + "' (valid: named, unnamed, wrong, passes)";
    u.recorded = Verdict(it - std::begin(kVerdicts));
    std::string source;
    if (auto e = mistakeSource(ex, u.change, source); !e.empty()) return at + ": " + u.change.name + ": " + e;
    // "mistake_lines" count from the body's first line; the body stands where the starter's region began.
    if (m.contains("mistake_lines") && m["mistake_lines"].is_array() && !u.change.body.empty()) {
      TodoRegion r;
      const std::string starter = readWholeFile(ex.dir / "starter" / u.change.file);
      const int first = findTodoRegion(starter, ex.id, r)
                            ? 1 + int(std::count(starter.begin(), starter.begin() + std::ptrdiff_t(r.from), '\n'))
                            : 1;
      for (auto& l : m["mistake_lines"])
        if (l.is_number_integer()) u.lines.push_back(first + l.get<int>() - 1);
    } else {
      u.lines = changedLines(source, labText(ex, u.change.file));
    }
    out.push_back(std::move(u));
  }
  return {};
}

// A diagnosis that states only what the frames or the function's table show (where they differ, how
// much, that they are the starter's), no cause: it cannot be wrong, though it may not name the cause either.
bool evidenceOnly(const std::string& explanation) {
  return explanation == "evidence" || explanation == "starter-result" || explanation.rfind("where:", 0) == 0 ||
         explanation.rfind("only:", 0) == 0 || explanation.rfind("probe:only:", 0) == 0 ||
         explanation == "probe:starter" || explanation.rfind("seen:", 0) == 0;
}

// The grading of the class the check writes: each submission's exercise entry of report.json.
std::map<std::string, nlohmann::json> gradeAsClass(const Exercise& ex, const fs::path& work,
                                                   const std::vector<std::string>& courseArgs,
                                                   const std::vector<UnlistedMistake>& unlisted,
                                                   const std::vector<std::string>& mutantFiles, std::string& error) {
  const fs::path cls = work / "class", out = work / "out";
  // The solution: the lab's own files (a part file: its functions as the lab defines them).
  for (auto& file : ex.files)
    if (auto e = writeTextFile((cls / "solution" / file).string(), labText(ex, file)); !e.empty()) {
      error = e;
      return {};
    }
  for (auto& m : ex.mistakes)
    if (auto e = writeMistakeFolder(ex, m, cls / (m.starter ? "starter" : "mistake-" + m.name)); !e.empty()) {
      error = e;
      return {};
    }
  for (auto& c : ex.correct)
    if (auto e = writeMistakeFolder(ex, c, cls / ("correct-" + c.name)); !e.empty()) {
      error = e;
      return {};
    }
  for (auto& u : unlisted)
    if (auto e = writeMistakeFolder(ex, u.change, cls / ("unlisted-" + u.change.name)); !e.empty()) {
      error = e;
      return {};
    }
  for (size_t k = 0; k < mutantFiles.size(); ++k)
    if (auto e = writeTextFile((cls / ("mutant-" + std::to_string(k + 1)) / ex.files.front()).string(), mutantFiles[k]);
        !e.empty()) {
      error = e;
      return {};
    }
  std::string command = "'" + fs::read_symlink("/proc/self/exe").string() + "' grade --class '" + cls.string() +
                        "' --exercise " + ex.id + " --jobs 2 --out '" + out.string() + "'";
  for (auto& dir : courseArgs) command += " --exercises '" + dir + "'";
  const fs::path log = work / "grade.log";
  const int status = std::system((command + " > '" + log.string() + "' 2>&1").c_str());
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    // The grader's own one-line reasons (a rubric's key, a starter that does not build), else all it said.
    const std::string said = readWholeFile(log);
    std::string reasons;
    for (size_t at = said.find("shadelab: "); at != std::string::npos; at = said.find("\nshadelab: ", at + 1)) {
      const size_t from = said[at] == '\n' ? at + 1 : at;
      reasons += (reasons.empty() ? "" : "; ") + said.substr(from + 10, said.find('\n', from) - from - 10);
    }
    error = reasons.empty() ? "grading the class failed: " + said : reasons;
    return {};
  }
  std::map<std::string, nlohmann::json> rows;
  for (auto& entry : fs::directory_iterator(out / "students")) {
    const nlohmann::json report = nlohmann::json::parse(readWholeFile(entry.path() / "report.json"), nullptr, false);
    if (report.is_object() && report.contains("exercises") && !report["exercises"].empty())
      rows[entry.path().filename().string()] = report["exercises"][0];
  }
  return rows;
}

// A check that only a broken frame fails (no NaN or Inf, values inside the view's range): it guards
// against what no listed mistake has to show, so no mistake needs to fail it.
bool isGuard(const Check& c) {
  return (c.metric == "non_finite_pct" || c.metric == "out_of_range_pct") && c.full.base == Threshold::Base::Absolute;
}

// A passing mutant known harmless: DIR/LAB/NAME.json {"harmless": [{"before", "after", "why"}]}.
struct HarmlessMutant {
  std::string before, after, why;
};
std::string loadHarmless(const Exercise& ex, const fs::path& dir, std::vector<HarmlessMutant>& out) {
  const fs::path file = dir / (ex.id + ".json");
  std::error_code ec;
  if (dir.empty() || !fs::is_regular_file(file, ec)) return {};
  const nlohmann::json j = nlohmann::json::parse(readWholeFile(file), nullptr, false);
  if (!j.is_object() || !j.contains("harmless") || !j["harmless"].is_array())
    return file.string() + ": must hold {\"harmless\": [{\"before\", \"after\", \"why\"}, ...]}";
  for (auto& h : j["harmless"]) {
    if (!h.is_object() || !h.contains("before") || !h.contains("after") || !h.contains("why") ||
        !h["before"].is_string() || !h["after"].is_string() || !h["why"].is_string())
      return file.string() + ": every harmless mutant needs \"before\", \"after\" and \"why\" (strings)";
    out.push_back({h["before"], h["after"], h["why"]});
  }
  return {};
}

// Every problem of one exercise, one line each; none when it is ready to go out.
std::vector<std::string> checkExercise(const Exercise& ex, const std::vector<std::string>& courseArgs,
                                       const std::vector<std::string>& unlistedDirs, const fs::path& mutantsDir,
                                       UnlistedTally& tally, std::string& summary) {
  std::vector<std::string> problems;
  for (auto& file : ex.files)
    if (auto e = starterMatchesLabFile(ex, file); !e.empty()) problems.push_back(e);
  std::vector<UnlistedMistake> unlisted;
  for (auto& dir : unlistedDirs)
    if (auto e = loadUnlisted(ex, dir, unlisted); !e.empty()) return {e};
  for (size_t i = 0; i < unlisted.size(); ++i)
    for (size_t j = 0; j < i; ++j)
      if (unlisted[i].change.name == unlisted[j].change.name)
        return {"unlisted mistake '" + unlisted[i].change.name + "' is named twice in the sets for " + ex.id};
  // Mutants of the solution's region of the first file, when asked for.
  std::vector<Mutant> mutants;
  std::vector<std::string> mutantFiles;
  std::vector<HarmlessMutant> harmless;
  if (!mutantsDir.empty()) {
    if (auto e = loadHarmless(ex, mutantsDir, harmless); !e.empty()) return {e};
    std::string before, region, after;
    if (solutionRegion(ex, ex.files.front(), before, region, after)) {
      mutants = mutate(region);
      for (auto& m : mutants) mutantFiles.push_back(before + m.text + after);
    }
  }
  const fs::path work = fs::temp_directory_path() / ("shadelab-exercise-check-" + std::to_string(getpid()));
  std::error_code ec;
  fs::remove_all(work, ec);
  std::string error;
  const auto rows = gradeAsClass(ex, work, courseArgs, unlisted, mutantFiles, error);
  fs::remove_all(work, ec);
  if (!error.empty()) return {error};
  const auto row = [&](const std::string& name) -> const nlohmann::json& {
    static const nlohmann::json none = nlohmann::json::object();
    const auto it = rows.find(name);
    return it == rows.end() ? none : it->second;
  };
  const auto percent = [](const nlohmann::json& e) { return e.value("percent", -1.0); };

  const nlohmann::json& solution = row("solution");
  if (percent(solution) != 100.0)
    problems.push_back("the lab's own file scores " + formatNumber(percent(solution)) + " %, not 100 %");
  for (auto& c : ex.correct) {
    const nlohmann::json& e = row("correct-" + c.name);
    if (percent(e) != 100.0 || e.contains("diagnosis"))
      problems.push_back("correct variant '" + c.name + "' scores " + formatNumber(percent(e)) + " %" +
                         (e.contains("diagnosis") ? " and is diagnosed: " + e["diagnosis"].get<std::string>() : "") +
                         ": a check is tighter than the answer");
  }
  const nlohmann::json& starter = row("starter");
  if (!(percent(starter) >= 0.0 && percent(starter) < kStarterBelow))
    problems.push_back("the starter scores " + formatNumber(percent(starter)) +
                       " %: under 30 % leaves the exercise to do");
  for (auto& c : starter.value("checks", nlohmann::json::array()))
    if (!c["errors"].empty()) {
      problems.push_back("the starter does not build: " + c["errors"][0].get<std::string>());
      break;
    }
  if (starter.value("mistake", "") != "starter")
    problems.push_back("the untouched starter is not told it is the starter (diagnosed: " +
                       starter.value("diagnosis", std::string("nothing")) + ")");
  size_t named = 0;
  for (auto& m : ex.mistakes) {
    if (m.starter) continue;
    const nlohmann::json& e = row("mistake-" + m.name);
    if (!(percent(e) < 100.0)) problems.push_back("mistake '" + m.name + "' loses no points: no check sees it");
    if (e.value("mistake", "") != m.name)
      problems.push_back("mistake '" + m.name + "' is diagnosed as " +
                         (e.contains("mistake") ? "'" + e["mistake"].get<std::string>() + "'" : "nothing") +
                         ": its frames are not told apart from the others'");
    else
      ++named;
  }
  // Each check fails for some submission that should not pass, and each hint reaches one of them.
  std::map<std::string, std::pair<bool, bool>> checks;  // "configuration: check" -> (failed, hint shown)
  std::map<std::string, std::string> hints;
  for (const auto& [name, e] : rows) {
    // The unlisted set measures the diagnoses; it never stands in for the rubric's own mistakes.
    if (name == "solution" || name.rfind("correct-", 0) == 0 || name.rfind("unlisted-", 0) == 0 ||
        name.rfind("mutant-", 0) == 0)
      continue;
    for (auto& c : e.value("checks", nlohmann::json::array())) {
      const std::string key = c["configuration"].get<std::string>() + ": " + c["check"].get<std::string>();
      auto& [failed, shown] = checks[key];
      const std::string hint = c.value("hint", ""), message = c.value("message", "");
      hints[key] = hint;
      if (c["result"] != "PASS") {
        failed = true;
        shown |= !hint.empty() && message.find(hint) != std::string::npos;
      }
    }
  }
  std::map<std::string, bool> guards;
  for (auto& c : ex.configurations)
    for (auto& k : c.checks) guards[c.name + ": " + k.name] = isGuard(k);
  for (const auto& [key, state] : checks) {
    if (!state.first && !guards[key])
      problems.push_back("check '" + key + "' passes for the starter and every mistake: it cannot fail");
    else if (state.first && !hints[key].empty() && !state.second)
      problems.push_back("the hint of check '" + key +
                         "' is shown to nobody: its hint_when evidence never comes together for the starter or a "
                         "listed mistake (list the mistake it is for)");
  }
  summary = "solution " + formatNumber(percent(solution)) + " %, starter " + formatNumber(percent(starter)) + " %, " +
            std::to_string(named) + " of " + std::to_string(ex.mistakes.size() - 1) + " mistakes named, " +
            std::to_string(ex.correct.size()) + " correct variants, " + std::to_string(checks.size()) + " checks";
  if (!mutantsDir.empty()) {
    // A mutant that does not build, or draws what the solution draws everywhere, says nothing of
    // the rubric: set aside. Of the rest, those that pass are holes unless known harmless: a
    // passing mutant listed with why it does no harm wherever the lab calls the function is set
    // aside too, as an equivalent one is, and printed with its reason.
    size_t invalid = 0, equivalent = 0, killed = 0, unexplained = 0, harmlessPassing = 0;
    std::vector<std::string> passingLines;
    for (size_t k = 0; k < mutants.size(); ++k) {
      const Mutant& m = mutants[k];
      const nlohmann::json& e = row("mutant-" + std::to_string(k + 1));
      if (e.value("status", "") != "graded") {
        ++invalid;
        continue;
      }
      bool same = percent(e) == 100.0;
      for (auto& f : e.value("frames", nlohmann::json::array()))  // what it draws: a probe's table is not drawn
        same = same && (f.value("function", false) || f.value("distance", 1.0) <= kFramesDiffer);
      if (same) {
        ++equivalent;
        continue;
      }
      const std::string change =
          "line " + std::to_string(m.line) + " (" + m.kind + "): '" + m.before + "' -> '" + m.after + "'";
      if (!e.value("passed", false)) {
        ++killed;
        const std::string said = e.value("explanation", "");
        if (said.empty() || said == "evidence") {
          ++unexplained;
          std::printf("       mutant %s fails, no explanation names it\n", change.c_str());
        }
        continue;
      }
      const auto known = std::find_if(harmless.begin(), harmless.end(), [&](const HarmlessMutant& h) {
        return h.before == m.before && h.after == m.after;
      });
      std::printf("       mutant %s passes (%s %%)%s\n", change.c_str(), formatNumber(percent(e)).c_str(),
                  known == harmless.end() ? "" : (": harmless, " + known->why).c_str());
      if (known != harmless.end()) ++harmlessPassing;
      if (known == harmless.end())
        passingLines.push_back("mutant " + change + " passes (" + formatNumber(percent(e)) +
                               " %): add a configuration or tighten a check, or list it as harmless with why");
    }
    const size_t graded = mutants.size() - invalid - equivalent - harmlessPassing;
    const double score = graded ? 100.0 * double(killed) / double(graded) : 100.0;
    summary += "; mutants: " + std::to_string(mutants.size()) + " made, " + std::to_string(invalid) +
               " not building, " + std::to_string(equivalent) + " equivalent, " +
               (harmlessPassing ? std::to_string(harmlessPassing) + " listed harmless, " : std::string()) +
               std::to_string(killed) + " of " + std::to_string(graded) + " fail (score " +
               formatNumber(std::round(score * 10.0) / 10.0) + " %), " + std::to_string(unexplained) +
               " with no explanation";
    if (score < 90.0)
      problems.push_back("mutation score " + formatNumber(std::round(score * 10.0) / 10.0) +
                         " %: under 90 % of the mutants that draw differently fail the rubric");
    problems.insert(problems.end(), passingLines.begin(), passingLines.end());
  }
  if (unlisted.empty()) return problems;
  size_t unlistedNamed = 0, wrong = 0, passing = 0;
  for (auto& u : unlisted) {
    const nlohmann::json& e = row("unlisted-" + u.change.name);
    const std::string said = e.value("explanation", "");
    // A trace names the line where the values part: it names the mistake when that line holds it.
    // Elsewhere it still states only what the values show (every claim of it measured), so it is
    // evidence that did not reach the cause: unnamed, and counted apart.
    const bool traced = said.rfind("line:", 0) == 0;
    const bool namesItsLine =
        traced && std::find(u.lines.begin(), u.lines.end(), std::atoi(said.c_str() + 5)) != u.lines.end();
    const Verdict v = e.value("passed", false) || !(percent(e) < 100.0)                        ? Verdict::Passes
                      : std::find(u.namedBy.begin(), u.namedBy.end(), said) != u.namedBy.end() ? Verdict::Named
                      : namesItsLine                                                           ? Verdict::Named
                      : evidenceOnly(said) || traced                                           ? Verdict::Unnamed
                                                                                               : Verdict::Wrong;
    unlistedNamed += v == Verdict::Named;
    tally.tracedElsewhere += traced && v == Verdict::Unnamed;
    wrong += v == Verdict::Wrong;
    passing += v == Verdict::Passes;
    std::printf("       unlisted %-34s %-7s %s\n", u.change.name.c_str(), kVerdicts[int(v)], said.c_str());
    if (const std::string told = e.value("diagnosis", std::string()); !told.empty())
      std::printf("                %s\n", told.c_str());  // to be read against the mistake
    if (v < u.recorded)
      problems.push_back("unlisted mistake '" + u.change.name + "' " + kVerdicts[int(v)] + " (it was " +
                         kVerdicts[int(u.recorded)] + "; " + formatNumber(percent(e)) +
                         " %): " + e.value("diagnosis", std::string()));
  }
  summary += "; unlisted: " + std::to_string(unlistedNamed) + " of " + std::to_string(unlisted.size()) + " named, " +
             std::to_string(wrong) + " wrongly, " + std::to_string(passing) + " passing";
  tally.mistakes += unlisted.size();
  tally.named += unlistedNamed;
  tally.wrong += wrong;
  tally.passing += passing;
  return problems;
}

int runExerciseCheck(const Options& o) {
  std::vector<std::string> ids;
  std::vector<std::string> courseArgs = o.exerciseDirs;
  const std::string target = o.positional.size() > 1 ? o.positional[1] : "";
  std::error_code ec;
  if (target.empty()) {
    ids = listExercises();
  } else if (fs::is_regular_file(fs::path(target) / "rubric.json", ec)) {  // one exercise's folder: ROOT/LAB/NAME
    fs::path dir = fs::absolute(target).lexically_normal();
    if (dir.filename().empty()) dir = dir.parent_path();  // a trailing slash
    courseArgs.insert(courseArgs.begin(), dir.parent_path().parent_path().string());
    setCourseFolders({courseArgs.begin(), courseArgs.end()});
    ids.push_back(dir.parent_path().filename().string() + "/" + dir.filename().string());
  } else if (fs::is_directory(target, ec)) {  // a course folder
    courseArgs.insert(courseArgs.begin(), target);
    setCourseFolders({courseArgs.begin(), courseArgs.end()});
    ids = listExercises(target);
    if (ids.empty()) {
      std::fprintf(stderr, "exercise check: %s holds no exercise (LAB/NAME/rubric.json)\n", target.c_str());
      return 1;
    }
  } else {
    ids.push_back(target);
  }
  int failed = 0;
  UnlistedTally tally;
  for (auto& id : ids) {
    Exercise ex;
    if (auto e = loadExercise(id, ex); !e.empty()) {
      std::printf("FAIL %s: %s\n", id.c_str(), e.c_str());
      ++failed;
      continue;
    }
    std::string summary;
    const std::vector<std::string> problems = checkExercise(ex, courseArgs, o.unlisted, o.mutants, tally, summary);
    std::printf("%s %s%s\n", problems.empty() ? "ok  " : "FAIL", id.c_str(),
                summary.empty() ? "" : (" (" + summary + ")").c_str());
    for (auto& p : problems) std::printf("       %s\n", p.c_str());
    std::fflush(stdout);
    failed += !problems.empty();
  }
  if (tally.mistakes > 0) {
    // Coverage: the mistakes named with their cause or their line. Precision: of the diagnoses given
    // (a mistake that passes has none), those that state nothing false about the code.
    const size_t diagnosed = tally.mistakes - tally.passing;
    std::printf(
        "unlisted in all: %zu of %zu named (coverage %s %%), %zu of %zu diagnoses false (precision %s %%), "
        "%zu passing; %zu traced to a line that does not hold the mistake\n",
        tally.named, tally.mistakes, formatFixed(100.0 * double(tally.named) / double(tally.mistakes), 1).c_str(),
        tally.wrong, diagnosed,
        formatFixed(diagnosed ? 100.0 * double(diagnosed - tally.wrong) / double(diagnosed) : 100.0, 1).c_str(),
        tally.passing, tally.tracedElsewhere);
  }
  std::printf("exercise check: %zu exercises, %d not ready\n", ids.size(), failed);
  return failed ? 1 : 0;
}

// The placeholder a starter's TODO region returns: the function draws, and visibly does nothing.
std::string placeholderFor(const std::string& head) {
  const size_t type = head.find_first_not_of(" \t"), typeEnd = head.find_first_of(" \t", type);
  const std::string t = type == std::string::npos ? "" : head.substr(type, typeEnd - type);
  if (t == "void") return "";
  if (t == "float") return "  return 0.0;\n";
  if (t == "int" || t == "uint") return "  return " + t + "(0);\n";
  if (t == "bool") return "  return false;\n";
  if (t.rfind("vec", 0) == 0 || t.rfind("ivec", 0) == 0 || t.rfind("mat", 0) == 0) return "  return " + t + "(0.0);\n";
  return "  " + t + " placeholder;\n  return placeholder;  // replace: this returns no values you chose\n";
}

int runExerciseNew(const Options& o) {
  const auto fail = [](const std::string& why) {
    std::fprintf(stderr, "shadelab: exercise new: %s\n", why.c_str());
    return 1;
  };
  const std::string id = o.positional.size() > 1 ? o.positional[1] : "";
  const size_t slash = id.find('/');
  const std::string labId = id.substr(0, slash), name = slash == std::string::npos ? "" : id.substr(slash + 1);
  const auto lab = makeLab(labId);
  if (!lab) return fail("'" + id + "' is not LAB/NAME with a lab of `shadelab list`");
  if (name.empty() || name.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789-") != std::string::npos)
    return fail("the exercise's name '" + name + "' may hold only a-z, 0-9 and '-'");
  if (o.exerciseDirs.empty()) return fail("--exercises DIR is required: the course folder the exercise goes into");
  const size_t colon = o.function.rfind(':');
  if (colon == std::string::npos)
    return fail("--function FILE:NAME is required, e.g. common/lighting.glsl:reflectLights");
  const std::string file = o.function.substr(0, colon), function = o.function.substr(colon + 1);
  const ShaderSearchPath builtin({builtinShaderDir()});
  const fs::path source = builtin.resolve(file);
  if (source.empty()) return fail("--function: the lab's shaders have no file '" + file + "'");
  const std::string text = readWholeFile(source);
  const std::vector<FunctionSpan> spans = findFunctions(text);
  const auto span = std::find_if(spans.begin(), spans.end(), [&](const FunctionSpan& s) { return s.name == function; });
  if (span == spans.end()) {
    std::string names;
    for (auto& s : spans) names += (names.empty() ? "" : ", ") + s.name;
    return fail("--function: " + file + " defines no function '" + function + "' (it defines: " + names + ")");
  }
  const fs::path dir = fs::path(o.exerciseDirs.front()) / labId / name;
  std::error_code ec;
  if (fs::exists(dir, ec)) return fail(dir.string() + " already exists; nothing is overwritten");

  // The starter: the function with its body cut to a TODO region, as a part file.
  const std::string whole = linesOf(text, *span);
  const size_t open = whole.find('{'), close = whole.rfind('}');
  const std::string head = whole.substr(0, open + 1), marker = "TODO(exercise " + id + ")";
  const std::string starter = "// " + function + "() of " + file + ", as a part file: ShadeLab puts it in place of\n" +
                              "// the lab's own wherever a program reads " + file + ".\n" + head + "\n  // " + marker +
                              ": begin\n" + placeholderFor(head) + "  // " + marker + ": end\n" + whole.substr(close) +
                              (whole.back() == '\n' ? "" : "\n");
  // The rubric: the lab's defaults, against the solution and (where the lab has one) the truth.
  nlohmann::json checks = nlohmann::json::array();
  checks.push_back({{"name", "matches the solution"},
                    {"metric", "covered_rmse"},
                    {"against", "solution"},
                    {"full", 0.004},
                    {"partial", 0.02},
                    {"points", 3},
                    {"hint", "Your frame differs from the solution's: say here where to look first."}});
  const Judge* judge = lab->judge();
  if (judge && !judge->plots().empty() && referenceOf(*lab).kind == TruthKind::Image)
    checks.push_back({{"name", "against the truth"},
                      {"metric", judge->plots().front().error},
                      {"against", "truth"},
                      {"full", "solution+0.002"},
                      {"partial", "solution+0.01"},
                      {"points", 1},
                      {"hint", "Your frame is further from the lab's truth than the solution's."}});
  const nlohmann::json rubric = {
      {"title", "TODO: the exercise's title"},
      {"lab", labId},
      {"level", "guided"},
      {"files", {file + std::string(kPartSuffix)}},
      {"pass_mark", 70},
      {"size", {320, 240}},
      {"configurations",
       {{{"name", "the lab's defaults"}, {"scene", std::string(lab->defaultScene())}, {"checks", checks}}}},
      {"mistakes", nlohmann::json::array()},
      {"correct", nlohmann::json::array()}};
  const std::string statement =
      "# TODO: the exercise's title\n\n**Lab:** `" + labId + "` · **File you edit:** `" + file +
      std::string(kPartSuffix) + "` (a part file: `" + function + "()` of `" + file +
      "`)\n\nTODO: what the function computes, the formula, what the starter draws.\n\n"
      "```sh\ncp -r starter/. my_shaders/\nbuild/shadelab grade --exercises COURSE --exercise " +
      id + " --shaders my_shaders\n```\n";
  for (auto& [path, content] :
       {std::pair{dir / "starter" / (file + std::string(kPartSuffix)), starter},
        std::pair{dir / "rubric.json", rubric.dump(2) + "\n"}, std::pair{dir / "statement.md", statement}})
    if (auto e = writeTextFile(path.string(), content); !e.empty()) return fail(e);
  std::printf("exercise new: %s in %s (the starter %s, rubric.json, statement.md)\n", id.c_str(), dir.string().c_str(),
              (file + std::string(kPartSuffix)).c_str());
  std::printf(
      "next: write the statement and the title, list the mistakes students make and two or three right\n"
      "answers written differently, then: shadelab exercise check %s\n",
      dir.string().c_str());
  return 0;
}

}  // namespace

int runExercise(const Options& o) {
  const std::string verb = o.positional.empty() ? "" : o.positional[0];
  if (verb == "check") return runExerciseCheck(o);
  if (verb == "new") return runExerciseNew(o);
  std::fprintf(stderr, "shadelab: exercise: '%s' is not a verb (valid: new, check)\n", verb.c_str());
  return 2;
}

}  // namespace shadelab

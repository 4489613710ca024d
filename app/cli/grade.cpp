// shadelab grade: renders every configuration of an exercise's rubric with the student's shaders
// (each in a child process under a watchdog), scores the checks and writes the reports.
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "app/cli/commands.h"
#include "app/cli/grade_render.h"
#include "app/cli/grade_student.h"
#include "app/grade/configuration_frames.h"
#include "app/grade/diagnosis.h"
#include "app/grade/gradebooks.h"
#include "app/grade/grading.h"
#include "app/grade/watchdog.h"
#include "app/measure/report.h"
#include "app/util/format.h"
#include "app/util/output_files.h"

namespace shadelab {

namespace fs = std::filesystem;

namespace {

constexpr int kCannotGrade = 2;
constexpr double kSolutionSeconds = 600.0;  // the built-in solution and its truth: generous, never the student's fault

// The checks of one configuration, from what its child wrote and how it ended. Returns "" or why
// the grader itself cannot go on (a rubric or solution at fault).
std::string scoreConfiguration(const ConfigurationJob& job, const WatchedRun& run, double watchdog,
                               const nlohmann::json& solution, const nlohmann::json& student,
                               ConfigurationResult& out) {
  const Configuration& c = *job.configuration;
  if (solution.contains("error")) return solution["error"].get<std::string>();
  if (!solution.contains("renderer"))
    return "configuration '" + c.name + "': the solution's frame was not made (" + run.describe() + ")";
  if (c.function < 0) out.solutionImage = job.stem + "-solution.png";  // a function's table is not a picture
  std::string why;                                                     // why nothing the student drew can be scored
  if (run.end == WatchedRun::End::TimedOut) {
    char s[160];
    std::snprintf(s, sizeof s,
                  "stopped by the watchdog after %.0f s: the shader ran too long (an unbounded loop?); nothing drawn "
                  "was scored",
                  watchdog);
    why = s;
    out.outcome = Outcome::TimedOut;
  } else if (student.is_null()) {
    why = "the renderer died drawing the student's shader (" + run.describe() + ")";
    out.outcome = Outcome::Crashed;
  }
  if (student.is_object() && c.function < 0) {
    out.studentImage = job.stem + "-student.png";
    out.diffImage = job.stem + "-diff.png";
  }
  return scoreChecks(*job.exercise, c, solution, student, why, out);
}

// Grades one exercise into `out`; returns "" or why it could not be graded.
std::string gradeExercise(const std::string& id, const StudentGrading& g, ExerciseResult& out, std::string& renderer,
                          CacheCount& cache) {
  Exercise ex;
  if (auto e = loadExercise(id, ex); !e.empty()) return e;
  out = ExerciseResult{};
  out.id = ex.id;
  out.title = ex.title;
  out.lab = ex.lab;
  out.total = ex.totalPoints();
  out.passMark = ex.passMark;
  out.notes = g.notes;
  std::printf("%s: %s (%s)\n", ex.id.c_str(), ex.title.c_str(), (ex.dir / "statement.md").c_str());
  lookUpSubmission(ex, g.shaderDirs, out);
  const auto jobOf = [&](size_t i) {
    const Configuration& c = ex.configurations[i];
    return ConfigurationJob{&ex,          &c,
                            g.shaderDirs, g.backend,
                            g.dir,        gradeSlug(ex.id) + "-" + std::to_string(i + 1) + "-" + gradeSlug(c.name),
                            g.cache,      solutionKeyBase(ex, i)};
  };
  for (size_t i = 0; i < ex.configurations.size(); ++i) {
    const Configuration& c = ex.configurations[i];
    ConfigurationResult result;
    result.name = c.name;
    result.description = describeConfiguration(c);
    result.visibility = c.visibility;
    if (!out.missingFiles.empty()) {
      notSubmitted(c, out.missingFiles.front() + " is in none of the --shaders folders", result);
    } else {
      ConfigurationJob job = jobOf(i);
      job.traceInDraw = traceInDrawNext(ex, out.configurations);
      WatchedRun run = runWatched([&](const auto& enter) { return renderConfiguration(job, enter); },
                                  [&](const std::string& phase) {
                                    return phase == "student" || phase == "trace" ? g.watchdog : kSolutionSeconds;
                                  },
                                  (g.dir / "logs" / (job.stem + ".log")).string());
      const nlohmann::json solution = readResult(job, "solution");
      nlohmann::json student = readResult(job, "student");
      const nlohmann::json trace = readResult(job, "trace");
      for (const char* phase : {"solution", "student", "trace"}) fs::remove(g.dir / (job.stem + "-" + phase + ".json"));
      if (job.traceInDraw && student.is_object()) {
        // The trace comes after the frame was scored: stopped or crashed there, the frame still counts.
        if (trace.is_object())
          student.update(trace);
        else if (run.phase == "trace" && (run.end != WatchedRun::End::Exited || run.status != 0))
          student["trace_unavailable"] = "tracing your function in the lab's draw " + run.describe();
        if (run.phase == "trace") run = {};
      }
      if (auto e = scoreConfiguration(job, run, g.watchdog, solution, student, result); !e.empty()) return e;
      if (renderer.empty()) renderer = solution.value("renderer", "");
      ++(solution.value("from_cache", false) ? cache.fromCache : cache.rendered);
    }
    for (auto& r : result.checks) out.earned += r.earned;
    out.configurations.push_back(std::move(result));
  }
  // The lines once every configuration is in: a hint may rest on another configuration's checks.
  diagnose(ex, out);
  if (slipsNeeded(out)) {
    // The solution's slips, for a diagnosis that no listed mistake settles: drawn in a second pass
    // (once, then from the cache) where the first had none, and the exercise diagnosed again.
    for (size_t i = 0; i < out.configurations.size(); ++i) {
      ConfigurationResult& result = out.configurations[i];
      if (!result.drawn || result.slipsDrawn) continue;
      ConfigurationJob job = jobOf(i);
      job.slips = true;
      runWatched([&](const auto& enter) { return renderConfiguration(job, enter); },
                 [&](const std::string& phase) { return phase == "student" ? g.watchdog : kSolutionSeconds; },
                 (g.dir / "logs" / (job.stem + "-slips.log")).string());
      const nlohmann::json solution = readResult(job, "solution"), distances = readResult(job, "slips");
      for (const char* phase : {"solution", "slips"}) fs::remove(g.dir / (job.stem + "-" + phase + ".json"));
      if (solution.contains("error")) return solution["error"].get<std::string>();
      addSlipEvidence(solution, distances, result);
    }
    diagnose(ex, out);
  }
  for (auto& line : diagnosisLines(out)) std::printf("%s\n", line.c_str());
  std::vector<std::string> printed;
  for (auto& c : out.configurations)
    for (auto& line : configurationLines(c, printed)) std::printf("%s\n", line.c_str());
  for (auto& f : out.missingFiles) std::printf("  not submitted: %s is in none of the --shaders folders\n", f.c_str());
  for (auto& n : out.notes) std::printf("  note: %s\n", n.c_str());
  std::printf("%s\n\n", exerciseTotalLine(out).c_str());
  return {};
}

}  // namespace

int cannotGrade(const std::string& message) {
  std::fprintf(stderr, "shadelab: grade: %s\n", message.c_str());
  return kCannotGrade;
}

std::string gradeDate() { return localTimeNow("%Y-%m-%d %H:%M"); }

SolutionCache solutionCacheFor(const Options& o) {
  if (o.noCache) return {};
  return SolutionCache(o.cacheDir.empty() ? defaultSolutionCacheDir() : fs::path(o.cacheDir));
}

std::string gradeSlug(const std::string& s) {
  std::string out;
  for (char ch : s) out += std::isalnum(static_cast<unsigned char>(ch)) ? char(std::tolower(ch)) : '-';
  return out;
}

bool pathInside(const fs::path& child, const fs::path& parent) {
  const fs::path c = fs::weakly_canonical(child), p = fs::weakly_canonical(parent);
  auto [pe, ce] = std::mismatch(p.begin(), p.end(), c.begin(), c.end());
  return pe == p.end();
}

std::string gradeStudent(const std::vector<std::string>& ids, const StudentGrading& g, GradeReport& report,
                         CacheCount& cache) {
  for (auto& id : ids) {
    ExerciseResult result;
    if (auto e = gradeExercise(id, g, result, report.renderer, cache); !e.empty()) return e;
    report.exercises.push_back(std::move(result));
  }
  for (auto& [name, text] :
       {std::pair{"report.md", gradeMarkdown(report)}, std::pair{"report.html", gradeHtml(report, g.dir)},
        std::pair{"report.json", gradeJson(report)}})
    if (auto e = writeTextFile((g.dir / name).string(), text); !e.empty()) return e;
  return {};
}

std::string prepareSolutions(const std::vector<std::string>& ids, const std::string& backend,
                             const SolutionCache& cache, const fs::path& scratch, CacheCount& count, bool slips) {
  for (auto& id : ids) {
    Exercise ex;
    if (auto e = loadExercise(id, ex); !e.empty()) return e;
    for (size_t i = 0; i < ex.configurations.size(); ++i) {
      ConfigurationJob job{
          &ex,     &ex.configurations[i],
          {},      backend,
          scratch, gradeSlug(ex.id) + "-" + std::to_string(i + 1) + "-" + gradeSlug(ex.configurations[i].name),
          cache,   solutionKeyBase(ex, i),
          true,    slips};
      const WatchedRun run =
          runWatched([&](const auto& enter) { return renderConfiguration(job, enter); },
                     [](const std::string&) { return kSolutionSeconds; }, (scratch / (job.stem + ".log")).string());
      const nlohmann::json solution = readResult(job, "solution");
      fs::remove(scratch / (job.stem + "-solution.json"));
      if (solution.contains("error")) return solution["error"].get<std::string>();
      if (!solution.contains("renderer"))
        return ex.id + ": configuration '" + ex.configurations[i].name + "': the solution's frame was not made (" +
               run.describe() + ")";
      ++(solution.value("from_cache", false) ? count.fromCache : count.rendered);
    }
  }
  return {};
}

int runGradePrepare(const Options& o) {
  if (o.exercise.empty() == !o.allExercises)
    return cannotGrade("--prepare: name one exercise (--exercise LAB/NAME) or --all");
  if (!o.shaderDirs.empty() || !o.classDir.empty() || !o.format.empty())
    return cannotGrade("--prepare fills the solution cache only: it takes no --shaders, --class or --format");
  const SolutionCache cache = solutionCacheFor(o);
  if (!cache.enabled()) return cannotGrade("--prepare fills the solution cache: not with --no-cache");
  const std::vector<std::string> ids = o.allExercises ? listExercises() : std::vector<std::string>{o.exercise};
  std::error_code ec;
  const fs::path scratch = fs::temp_directory_path(ec) / ("shadelab-prepare-" + std::to_string(getpid()));
  fs::create_directories(scratch, ec);
  if (ec) return cannotGrade(scratch.string() + ": " + ec.message());
  CacheCount count;
  const std::string e = prepareSolutions(ids, o.backend, cache, scratch, count, true);
  fs::remove_all(scratch, ec);
  if (!e.empty()) return cannotGrade(e);
  std::printf("solutions: %d configurations of %zu exercise%s, %d already in the cache, %d rendered (%s)\n",
              count.fromCache + count.rendered, ids.size(), ids.size() == 1 ? "" : "s", count.fromCache, count.rendered,
              cache.dir().c_str());
  return 0;
}

int runGrade(const Options& o) {
  if (o.prepare) return runGradePrepare(o);
  if (!o.classDir.empty()) return runGradeClass(o);
  if (!o.positional.empty()) return runGradeMerge(o);
  if (o.exercise.empty() == !o.allExercises)
    return cannotGrade("name one exercise (--exercise LAB/NAME) or --all; exercises: see `shadelab list`");
  if (o.shaderDirs.empty())
    return cannotGrade("--shaders DIR is required: the folder holding the student's shader files");
  if (o.jobs != 1 || o.shards != 1) return cannotGrade("--jobs and --shard are for a class (--class DIR)");
  if (o.format == "moodle" || o.format == "canvas")
    return cannotGrade("--format " + o.format +
                       " is a class's gradebook (--class DIR); one student: gradescope, classroom50, prairielearn");
  Classroom50Identity identity;
  if (o.format == "classroom50")
    if (auto e = classroom50IdentityFromEnvironment(identity); !e.empty())
      return cannotGrade(e + " (--format classroom50 runs in Classroom 50's runner: tools/classroom50/autograder.py)");
  std::vector<std::string> ids = o.allExercises ? listExercises() : std::vector<std::string>{o.exercise};
  if (ids.empty()) return cannotGrade("no exercises in " + builtinExercisesRoot().string() + " or a course folder");

  // The report folder: fresh, and never inside what is being graded (the student's folder is only read).
  fs::path dir =
      o.out.empty() ? freshName("grades", o.allExercises ? "all" : gradeSlug(o.exercise), "") : fs::path(o.out);
  for (auto& s : o.shaderDirs)
    if (pathInside(dir, s))
      return cannotGrade("--out " + dir.string() + " lies inside the graded folder " + s.string() +
                         ", which is only ever read; write the report elsewhere");
  std::error_code ec;
  if (fs::exists(dir / "report.json"))
    return cannotGrade("--out " + dir.string() + " already holds a report; nothing is overwritten");
  fs::create_directories(dir / "logs", ec);
  if (ec) return cannotGrade("--out " + dir.string() + ": " + ec.message());

  StudentGrading g;
  g.shaderDirs = o.shaderDirs;
  g.dir = dir;
  g.backend = o.backend;
  g.watchdog = o.watchdog;
  g.cache = solutionCacheFor(o);
  GradeReport report;
  for (auto& d : o.shaderDirs) report.studentDirs.push_back(d.string());
  report.date = gradeDate();
  report.command = "shadelab grade " + (o.allExercises ? std::string("--all") : "--exercise " + o.exercise);
  for (auto& d : o.shaderDirs) report.command += " --shaders " + d.string();
  CacheCount cache;
  if (auto e = gradeStudent(ids, g, report, cache); !e.empty()) return cannotGrade(e);
  if (!o.format.empty()) {
    const nlohmann::json j = nlohmann::json::parse(gradeJson(report));
    const nlohmann::json results = o.format == "gradescope"    ? gradescopeResults(j, "visible", dir)
                                   : o.format == "classroom50" ? classroom50Result(j, identity)
                                                               : prairieLearnResults(j, dir);
    const char* file = o.format == "classroom50" ? "result.json" : "results.json";
    if (auto e = writeTextFile((dir / file).string(), results.dump(2) + "\n"); !e.empty()) return cannotGrade(e);
    if (o.format == "classroom50" && wholePointScale(j) != 1)
      std::printf("classroom50: every check's points x%d, so that each is whole\n", wholePointScale(j));
  }

  double earned = 0, total = 0;
  bool passed = true;
  for (auto& e : report.exercises) {
    earned += e.earned;
    total += e.total;
    passed &= e.passed();
  }
  if (report.exercises.size() > 1)
    std::printf("all: %g / %g points (%.1f%%), %s\n", std::round(earned * 100) / 100, total,
                total > 0 ? 100.0 * earned / total : 0.0,
                passed ? "every exercise passed" : "not every exercise passed");
  if (g.cache.enabled())
    std::printf("solutions: %d of %d configurations from the cache (%s)\n", cache.fromCache,
                cache.fromCache + cache.rendered, g.cache.dir().c_str());
  std::printf("report: %s (also report.md, report.json%s)\n", (dir / "report.html").c_str(),
              o.format == "gradescope"     ? ", results.json for Gradescope"
              : o.format == "classroom50"  ? ", result.json for Classroom 50"
              : o.format == "prairielearn" ? ", results.json for PrairieLearn"
                                           : "");
  return passed ? 0 : 1;
}

}  // namespace shadelab

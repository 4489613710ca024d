// shadelab grade --class DIR: every submission in a folder, each graded as `grade --shaders` grades
// one (every configuration in its own child under the watchdog), N at a time, in a deterministic
// slice of the class when sharded; then a gradebook and a class page. `grade merge` joins the
// outputs of shards into what one run over the whole class would have written.
//
// Layout of --out:
//   class.json        what was graded: exercises, this shard, its students
//   gradebook.csv     one row per student and exercise
//   class.html        the class page
//   students/NAME/    each student's report (as `grade --shaders` writes it) and grade.log
//   logs/             the solutions' logs
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <fstream>
#include <map>

#include <nlohmann/json.hpp>

#include "app/cli/commands.h"
#include "app/cli/grade_student.h"
#include "app/cli/submissions.h"
#include "app/grade/class_report.h"
#include "app/grade/gradebooks.h"
#include "app/grade/rubric.h"
#include "app/measure/report.h"
#include "app/util/format.h"
#include "app/util/output_files.h"
#include "app/util/read_file.h"

namespace shadelab {

namespace fs = std::filesystem;

namespace {

// What every submission of a run is graded with besides its own files.
struct ClassRun {
  std::vector<std::string> ids;    // the exercises
  std::vector<std::string> files;  // their files, which each upload is placed into (placeUpload)
  // One student's results for a platform (--format gradescope, classroom50, prairielearn: a class
  // of one upload, as each platform's entry point grades it), written beside their report.
  std::string format;
  Classroom50Identity identity;
  int wholeScale = 1;  // Classroom 50's factor, the rubrics'
};

// The platform's file for one student, beside their report in `dir`. "" or why it was not written.
std::string writeStudentResults(const ClassRun& run, const GradeReport& report, const fs::path& dir) {
  if (run.format != "gradescope" && run.format != "classroom50" && run.format != "prairielearn") return {};
  const nlohmann::json j = nlohmann::json::parse(gradeJson(report));
  const nlohmann::json results = run.format == "gradescope"    ? gradescopeResults(j, "visible", dir)
                                 : run.format == "classroom50" ? classroom50Result(j, run.identity, run.wholeScale)
                                                               : prairieLearnResults(j, dir);
  return writeTextFile((dir / (run.format == "classroom50" ? "result.json" : "results.json")).string(),
                       results.dump(2) + "\n");
}

// The entries of a platform's download that hold a student's files (their folders, or the loose
// files themselves), as the report names what it graded.
std::vector<std::string> downloadEntries(const Submission& sub, const fs::path& classDir) {
  std::vector<std::string> entries;
  for (auto& [path, name] : sub.files) {
    const fs::path relative = path.lexically_relative(classDir);
    const std::string top = (classDir / *relative.begin()).string();
    if (std::find(entries.begin(), entries.end(), top) == entries.end()) entries.push_back(top);
  }
  return entries;
}

// Runs in a worker process: grades one submission into out/students/<name>/. Exit 0 when its
// report was written, 2 when the grader could not go on.
int gradeSubmission(const Submission& sub, const ClassRun& run, const Options& o, const fs::path& out,
                    const SolutionCache& cache) {
  StudentGrading g;
  g.dir = out / "students" / sub.name;
  g.backend = o.backend;
  g.watchdog = o.watchdog;
  g.cache = cache;
  std::error_code ec;
  fs::create_directories(g.dir / "logs", ec);
  if (ec) return cannotGrade(g.dir.string() + ": " + ec.message());
  if (FILE* log = std::freopen((g.dir / "grade.log").c_str(), "w", stdout)) dup2(fileno(log), STDERR_FILENO);

  fs::path upload = sub.source, unpacked;
  if (!sub.id.empty()) {  // a platform's download: the student's files gathered into a folder (maybe none)
    unpacked = upload = out / "unpacked" / sub.name;
    removeUnpacked(unpacked);
    if (auto e = stageFiles(sub, unpacked); !e.empty()) return cannotGrade(e);
    g.notes.insert(g.notes.end(), sub.notes.begin(), sub.notes.end());
  } else if (sub.zip) {
    unpacked = upload = out / "unpacked" / sub.name;
    removeUnpacked(unpacked);  // what an earlier, interrupted run left
    if (auto e = unpackZip(sub.source, unpacked); !e.empty()) {
      removeUnpacked(unpacked);
      fs::create_directories(unpacked, ec);  // graded as an empty folder: nothing submitted, and why
      g.notes.push_back("the zip was not unpacked: " + e);
      std::printf("%s\n", e.c_str());
    }
  }
  // The upload as the student made it, its files put where the rubric expects them.
  const fs::path placed = out / "placed" / sub.name;
  removeUnpacked(placed);
  Placement placement;
  const std::string shown = sub.id.empty() ? sub.source.filename().string() : sub.name;
  if (auto e = placeUpload(upload, run.files, placed, shown, placement); !e.empty()) return cannotGrade(e);
  for (auto& n : placement.notes) std::printf("%s: %s\n", sub.name.c_str(), n.c_str());
  g.notes.insert(g.notes.end(), placement.notes.begin(), placement.notes.end());
  g.shaderDirs = {placed};
  GradeReport report;
  report.studentDirs = {sub.source.string()};
  if (!sub.id.empty()) report.studentDirs = downloadEntries(sub, o.classDir);
  report.date = gradeDate();
  report.command = "shadelab grade --class " + o.classDir.string() + " (submission " + sub.name + ")";
  CacheCount count;
  std::string e = gradeStudent(run.ids, g, report, count);
  if (e.empty()) e = writeStudentResults(run, report, g.dir);
  if (!unpacked.empty()) removeUnpacked(unpacked);
  removeUnpacked(placed);
  if (!e.empty()) return cannotGrade(e);
  return 0;
}

struct Summary {
  int submissions = 0;
  std::map<std::string, int> statuses;
  std::string gradebook;             // the platform's file, where --format names one
  std::vector<std::string> leftOut;  // the students it leaves out, and why
};

// What the gradebooks need of the class folder besides the reports: its layout and, in a
// platform's download, who each submission is. Kept in class.json, so a merge of shards has it.
struct ClassIdentity {
  ClassLayout layout = ClassLayout::Named;
  PlatformIdentities identities;
};

nlohmann::json identityJson(const ClassIdentity& who) {
  nlohmann::json ids = nlohmann::json::object();
  for (auto& [name, id] : who.identities) ids[name] = {{"id", id.id}, {"person", id.person}};
  return {{"layout", layoutKey(who.layout)}, {"identities", ids}};
}

// class.json's layout and identities; "" or what is wrong with them. A record without them (an
// older run's) is a class of named folders.
std::string readIdentity(const nlohmann::json& j, ClassIdentity& who) {
  const std::string key = j.value("layout", "named");
  if (!layoutFromKey(key, who.layout)) return "layout '" + key + "' is none of named, moodle, canvas";
  for (auto& [name, id] : j.value("identities", nlohmann::json::object()).items())
    if (id.is_object()) who.identities[name] = {id.value("id", ""), id.value("person", "")};
  return {};
}

// Reads every student's report under out/students into the gradebook and the class page. A
// student whose report is missing (the grader itself failed on it) gets a "crashed" row per
// exercise. "" or why the outputs could not be written.
std::string writeClassOutputs(const fs::path& out, const std::vector<std::string>& ids,
                              const std::vector<std::string>& students, const std::string& format,
                              const ClassIdentity& who, Summary& summary) {
  std::vector<ClassRow> rows;
  for (auto& s : students) {
    const fs::path report = out / "students" / s / "report.json";
    if (fs::exists(report)) {
      if (auto e = readStudentRows(report, s, rows); !e.empty()) return e;
    } else {
      for (auto& id : ids) {
        ClassRow row;
        row.student = s;
        row.exercise = row.title = id;
        row.status = "crashed";
        rows.push_back(row);
      }
    }
  }
  summary.submissions = int(students.size());
  for (auto& r : rows) ++summary.statuses[r.status];
  for (auto& [name, text] :
       {std::pair{"gradebook.csv", gradebookCsv(rows)}, std::pair{"class.html", classHtml(rows, out / "students")}})
    if (auto e = writeTextFile((out / name).string(), text); !e.empty()) return e;
  GradebookFile file;
  if (format == "moodle" && who.layout == ClassLayout::Moodle) {
    summary.gradebook = "moodle-worksheet.csv";
    file = moodleWorksheetCsv(rows, who.identities, utcTimeNow("%Y-%m-%dT%H:%M:%SZ"));
  } else if (format == "moodle") {
    summary.gradebook = "moodle.csv";
    file = moodleCsv(rows);
  } else if (format == "canvas") {
    summary.gradebook = "canvas.csv";
    file = canvasCsv(rows, who.identities);
  } else {
    return {};
  }
  summary.leftOut = file.leftOut;
  return writeTextFile((out / summary.gradebook).string(), file.text);
}

nlohmann::json classJson(const std::vector<std::string>& ids, int shard, int shards,
                         const std::vector<std::string>& students, const ClassIdentity& who) {
  nlohmann::json j = {{"exercises", ids}, {"shard", shard}, {"shards", shards}, {"students", students}};
  j.update(identityJson(who));
  return j;
}

void printSummary(const fs::path& out, const Summary& s) {
  std::string line;
  for (Outcome o : {Outcome::Graded, Outcome::DidNotBuild, Outcome::TimedOut, Outcome::Crashed, Outcome::NotSubmitted})
    if (auto n = s.statuses.find(outcomeName(o)); n != s.statuses.end())
      line += (line.empty() ? "" : ", ") + std::to_string(n->second) + " " + n->first;
  std::printf("class: %d submissions (%s)\ngradebook: %s\nclass page: %s\n", s.submissions, line.c_str(),
              (out / "gradebook.csv").c_str(), (out / "class.html").c_str());
  if (s.gradebook.empty()) return;
  std::printf("%s: %s\n", s.gradebook.c_str(), (out / s.gradebook).c_str());
  if (!s.leftOut.empty()) {
    std::string who;
    for (auto& l : s.leftOut) who += (who.empty() ? "" : "; ") + l;
    std::printf(
        "%s leaves out %zu student%s, so the platform keeps the grade each has now (%s): grade again, or "
        "enter those grades by hand\n",
        s.gradebook.c_str(), s.leftOut.size(), s.leftOut.size() == 1 ? "" : "s", who.c_str());
  }
}

// A fresh output folder outside what is graded; "" or why not.
std::string prepareOut(const fs::path& out, const std::vector<fs::path>& graded) {
  for (auto& g : graded)
    if (pathInside(out, g))
      return "--out " + out.string() + " lies inside " + g.string() + ", which is only ever read; write elsewhere";
  std::error_code ec;
  if (fs::exists(out / "class.json", ec) || fs::exists(out / "gradebook.csv", ec))
    return "--out " + out.string() + " already holds a class's grades; nothing is overwritten";
  fs::create_directories(out / "students", ec);
  if (!ec) fs::create_directories(out / "logs", ec);
  return ec ? "--out " + out.string() + ": " + ec.message() : "";
}

}  // namespace

int runGradeClass(const Options& o) {
  if (o.exercise.empty() == !o.allExercises)
    return cannotGrade("name one exercise (--exercise LAB/NAME) or --all; exercises: see `shadelab list`");
  if (!o.shaderDirs.empty())
    return cannotGrade("--shaders and --class do not go together: --class DIR holds every student's folder");
  ClassRun run;
  run.ids = o.allExercises ? listExercises() : std::vector<std::string>{o.exercise};
  std::vector<Exercise> exercises;
  for (auto& id : run.ids) {
    Exercise ex;
    if (auto e = loadExercise(id, ex); !e.empty()) return cannotGrade(e);
    for (auto& f : ex.files)
      if (std::find(run.files.begin(), run.files.end(), f) == run.files.end()) run.files.push_back(f);
    exercises.push_back(std::move(ex));
  }
  ClassFolder folder;
  if (auto e = readClassFolder(o.classDir, folder); !e.empty()) return cannotGrade(e);
  const std::vector<Submission>& all = folder.submissions;
  ClassIdentity who{folder.layout, {}};
  for (auto& sub : all)
    if (!sub.id.empty()) who.identities[sub.name] = {sub.id, sub.person};
  // A platform's identities go only to that platform's gradebook: Moodle's participant ids mean
  // nothing to Canvas, which would match them against its own users.
  if ((o.format == "canvas" && folder.layout == ClassLayout::Moodle) ||
      (o.format == "moodle" && folder.layout == ClassLayout::Canvas))
    return cannotGrade("--format " + o.format + ": " + o.classDir.string() + " is " + layoutName(folder.layout) +
                       ", whose ids " + o.format + " does not know; grade it with --format " +
                       (o.format == "canvas" ? "moodle" : "canvas") + ", or lay the class out as a folder per student");
  if (folder.layout != ClassLayout::Named)
    std::printf("%s: read as %s (%zu students)\n", o.classDir.c_str(), layoutName(folder.layout), all.size());
  for (auto& i : folder.ignored) std::printf("  ignored: %s\n", i.c_str());
  if (all.empty())
    return cannotGrade("--class " + o.classDir.string() + " holds no submissions (a folder or a .zip per student)");
  if (o.format == "gradescope" || o.format == "classroom50" || o.format == "prairielearn") {
    if (all.size() != 1)
      return cannotGrade("--format " + o.format + " is one student's results: --class then holds one upload (" +
                         o.classDir.string() + " holds " + std::to_string(all.size()) + "); a class: moodle or canvas");
    run.format = o.format;
    run.wholeScale = wholePointScale(exercises);
    if (o.format == "classroom50")
      if (auto e = classroom50IdentityFromEnvironment(run.identity); !e.empty())
        return cannotGrade(e +
                           " (--format classroom50 runs in Classroom 50's runner: tools/classroom50/autograder.py)");
  }
  // The slice: every n-th submission by name, starting at the i-th. Which shard a student falls
  // in depends only on the sorted names, so every node computes the same split.
  std::vector<Submission> mine;
  for (size_t k = 0; k < all.size(); ++k)
    if (int(k % size_t(o.shards)) == o.shard - 1) mine.push_back(all[k]);

  const std::vector<std::string>& ids = run.ids;
  const fs::path out = o.out.empty()
                           ? freshName("grades", "class-" + gradeSlug(o.allExercises ? "all" : o.exercise), "")
                           : fs::path(o.out);
  if (auto e = prepareOut(out, {o.classDir}); !e.empty()) return cannotGrade(e);
  const SolutionCache cache = solutionCacheFor(o);
  std::printf("grading %zu of %zu submissions in %s (shard %d of %d), %zu exercise%s, %d at a time\n", mine.size(),
              all.size(), o.classDir.c_str(), o.shard, o.shards, ids.size(), ids.size() == 1 ? "" : "s", o.jobs);
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  if (cache.enabled()) {
    CacheCount count;
    if (auto e = prepareSolutions(ids, o.backend, cache, out / "logs", count); !e.empty()) return cannotGrade(e);
    std::printf("solutions: %d configurations, %d from the cache, %d rendered (%s)\n", count.fromCache + count.rendered,
                count.fromCache, count.rendered, cache.dir().c_str());
  }
  std::fflush(stdout);

  // Workers: one process per submission, at most --jobs at once. The parent holds no GL context
  // and no threads; each worker forks its own watched children.
  std::map<pid_t, const Submission*> running;
  bool failed = false;
  const auto reap = [&] {
    int status = 0;
    const pid_t pid = wait(&status);
    if (pid <= 0 || !running.count(pid)) return;
    const Submission& sub = *running[pid];
    running.erase(pid);
    std::vector<ClassRow> rows;
    const fs::path report = out / "students" / sub.name / "report.json";
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || !readStudentRows(report, sub.name, rows).empty()) {
      failed = true;
      std::printf("  %-24s not graded: the grader failed (see %s)\n", sub.name.c_str(),
                  (out / "students" / sub.name / "grade.log").c_str());
    }
    for (auto& r : rows)
      std::printf("  %-24s %-22s %5g / %-3g %s\n", sub.name.c_str(), r.exercise.c_str(),
                  std::round(r.score * 100) / 100, r.total, r.status.c_str());
    std::fflush(stdout);
  };
  for (auto& sub : mine) {
    while (int(running.size()) >= o.jobs) reap();
    std::fflush(nullptr);
    const pid_t pid = fork();
    if (pid == 0) _exit(gradeSubmission(sub, run, o, out, cache));
    if (pid < 0) return cannotGrade(std::string("cannot start a worker: ") + std::strerror(errno));
    running[pid] = &sub;
  }
  while (!running.empty()) reap();
  fs::remove_all(out / "unpacked");
  fs::remove_all(out / "placed");

  std::vector<std::string> names;
  for (auto& s : mine) names.push_back(s.name);
  Summary summary;
  if (auto e = writeClassOutputs(out, ids, names, o.format, who, summary); !e.empty()) return cannotGrade(e);
  if (auto e =
          writeTextFile((out / "class.json").string(), classJson(ids, o.shard, o.shards, names, who).dump(2) + "\n");
      !e.empty())
    return cannotGrade(e);
  printSummary(out, summary);
  std::printf("took %.1f s, %.2f s per submission\n", std::chrono::duration<double>(Clock::now() - start).count(),
              std::chrono::duration<double>(Clock::now() - start).count() / std::max<size_t>(1, mine.size()));
  return failed ? 1 : 0;
}

int runGradeMerge(const Options& o) {
  if (o.positional.empty() || o.positional[0] != "merge")
    return cannotGrade("unexpected argument '" + o.positional[0] + "'");
  const std::vector<std::string> dirs(o.positional.begin() + 1, o.positional.end());
  if (dirs.empty()) return cannotGrade("merge: name the shards' output folders: grade merge DIR... --out DIR");
  if (o.out.empty()) return cannotGrade("merge: --out DIR is required: where the joined gradebook and class page go");

  std::vector<std::string> ids, students;
  ClassIdentity who;
  std::map<int, std::string> shardDirs;
  int shards = 0;
  std::map<std::string, fs::path> from;  // student -> the shard folder holding their report
  for (auto& d : dirs) {
    const fs::path file = fs::path(d) / "class.json";
    std::string text;
    if (!readWholeFile(file, text))
      return cannotGrade("merge: " + file.string() + " cannot be read (not the output of grade --class)");
    const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
    if (j.is_discarded() || !j.is_object() || !j.contains("exercises") || !j["exercises"].is_array() ||
        !j.contains("students") || !j["students"].is_array() ||
        !j.value("shard", nlohmann::json()).is_number_integer() ||
        !j.value("shards", nlohmann::json()).is_number_integer())
      return cannotGrade("merge: " + file.string() + ": not a class record (needs exercises, students, shard, shards)");
    std::vector<std::string> theirs;
    for (auto& e : j["exercises"])
      if (e.is_string()) theirs.push_back(e.get<std::string>());
    const int shard = j["shard"].get<int>(), of = j["shards"].get<int>();
    ClassIdentity theirWho;
    if (auto e = readIdentity(j, theirWho); !e.empty()) return cannotGrade("merge: " + file.string() + ": " + e);
    if (!shardDirs.empty() && theirWho.layout != who.layout)
      return cannotGrade("merge: " + d + " read its class folder as " + layoutName(theirWho.layout) + ", " +
                         dirs.front() + " as " + layoutName(who.layout));
    who.layout = theirWho.layout;
    who.identities.insert(theirWho.identities.begin(), theirWho.identities.end());
    if (ids.empty()) {
      ids = theirs;
      shards = of;
    } else if (theirs != ids || of != shards) {
      return cannotGrade("merge: " + d + " graded other exercises or another split (" + std::to_string(of) +
                         " shards) than " + dirs.front());
    }
    if (shard < 1 || shard > of)
      return cannotGrade("merge: " + file.string() + ": shard " + std::to_string(shard) + " of " + std::to_string(of));
    if (shardDirs.count(shard))
      return cannotGrade("merge: shard " + std::to_string(shard) + " is given twice (" + shardDirs[shard] + " and " +
                         d + ")");
    shardDirs[shard] = d;
    for (auto& s : j["students"]) {
      if (!s.is_string()) continue;
      const std::string name = s.get<std::string>();
      if (name.empty() || name[0] == '.' || name.find('/') != std::string::npos)
        return cannotGrade("merge: " + file.string() + ": '" + name + "' is not a submission's name");
      if (from.count(name))
        return cannotGrade("merge: '" + name + "' was graded by two shards (" + from[name].string() + ", " + d + ")");
      from[name] = d;
      students.push_back(name);
    }
  }
  for (int i = 1; i <= shards; ++i)
    if (!shardDirs.count(i))
      return cannotGrade("merge: shard " + std::to_string(i) + " of " + std::to_string(shards) +
                         " is missing; give every shard's --out folder");

  const fs::path out = o.out;
  std::vector<fs::path> inputs(dirs.begin(), dirs.end());
  if (auto e = prepareOut(out, inputs); !e.empty()) return cannotGrade(e);
  std::sort(students.begin(), students.end());
  for (auto& s : students) {
    std::error_code ec;
    fs::copy(from[s] / "students" / s, out / "students" / s, fs::copy_options::recursive, ec);
    if (ec) return cannotGrade("merge: " + (from[s] / "students" / s).string() + ": " + ec.message());
  }
  Summary summary;
  if (auto e = writeClassOutputs(out, ids, students, o.format, who, summary); !e.empty()) return cannotGrade(e);
  if (auto e = writeTextFile((out / "class.json").string(), classJson(ids, 1, 1, students, who).dump(2) + "\n");
      !e.empty())
    return cannotGrade(e);
  printSummary(out, summary);
  return 0;
}

}  // namespace shadelab

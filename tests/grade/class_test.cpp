// `shadelab grade --class` end to end, through the real binary, on a class the test makes: the
// solution, the starter, seeded mistakes, a compile error, an endless loop, an empty folder, a zip
// and an include reaching into a neighbour's folder. Every submission gets the right row; shards
// merged equal the whole run; a second run takes the solutions from the cache and a changed
// built-in file or rubric misses it. Unpacking zips refuses entries that would leave the folder.
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>

#include <gtest/gtest.h>
#include <unistd.h>
#include <zip.h>
#include <nlohmann/json.hpp>

#include "app/cli/submissions.h"
#include "app/grade/rubric.h"
#include "app/shader/preprocessor.h"
#include "app/util/zip_writer.h"
#include "test_files.h"

namespace fs = std::filesystem;
using namespace shadelab;

namespace {

using test::readText;

void writeText(const fs::path& file, const std::string& text) {
  fs::create_directories(file.parent_path());
  std::ofstream(file, std::ios::binary) << text;
}

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::path(SHADELAB_TEST_OUT) / "grade-class" / name;
  if (fs::exists(dir)) {
    // Unpacked zips are read-only: give write back before removing.
    for (auto& e : fs::recursive_directory_iterator(dir))
      fs::permissions(e.path(), fs::perms::owner_all, fs::perm_options::add);
    fs::remove_all(dir);
  }
  fs::create_directories(dir);
  return dir;
}

// The lab's `file` with `find` (exactly once) replaced.
std::string labFileWith(const std::string& file, const std::string& find, const std::string& replace) {
  std::string text = readText(builtinShaderDir() / file);
  const size_t at = text.find(find);
  EXPECT_NE(at, std::string::npos) << file << " no longer holds: " << find;
  EXPECT_EQ(text.find(find, at + 1), std::string::npos) << find;
  if (at != std::string::npos) text.replace(at, find.size(), replace);
  return text;
}

std::string pcfWith(const std::string& find, const std::string& replace) {
  return labFileWith("shadows/pcf.glsl", find, replace);
}

const std::string kTap = "lit += tapCompare(type, L, map, cube, q, vec2(i, j) - 0.5 * float(PCF_SIZE - 1));";

// A zip holding `files` (name -> bytes), written with libzip.
void writeZip(const fs::path& zipFile, const std::map<std::string, std::string>& files) {
  int error = 0;
  zip_t* z = zip_open(zipFile.c_str(), ZIP_CREATE | ZIP_TRUNCATE, &error);
  ASSERT_NE(z, nullptr);
  for (auto& [name, bytes] : files) {
    zip_source_t* src = zip_source_buffer(z, bytes.data(), bytes.size(), 0);
    ASSERT_GE(zip_file_add(z, name.c_str(), src, ZIP_FL_ENC_UTF_8), 0) << name;
  }
  ASSERT_EQ(zip_close(z), 0);
}

// The PCF rubric's points in all.
double pcfTotal() {
  Exercise ex;
  EXPECT_EQ(loadExercise("shadows/pcf", ex), "");
  return ex.totalPoints();
}

size_t pcfConfigurations() {
  Exercise ex;
  EXPECT_EQ(loadExercise("shadows/pcf", ex), "");
  return ex.configurations.size();
}

// The class: name -> what it holds and the status and score its row must have.
struct Expected {
  std::string status;
  double score;  // < 0: below the pass mark, any value
};

std::map<std::string, Expected> makeClass(const fs::path& dir, bool withSlowOnes) {
  const std::string solution = readText(builtinShaderDir() / "shadows/pcf.glsl");
  writeText(dir / "ana/shadows/pcf.glsl", solution);
  Exercise ex;
  EXPECT_EQ(loadExercise("shadows/pcf", ex), "");
  fs::copy(ex.dir / "starter", dir / "ben", fs::copy_options::recursive);
  // The bias with the wrong sign: acne everywhere (tests/grade's seeded mistake).
  writeText(dir / "cara/shadows/pcf.glsl",
            pcfWith(kTap,
                    "{ vec2 o = vec2(i, j) - 0.5 * float(PCF_SIZE - 1); lit += receiverDepth(type, L, q, o) + q.bias > "
                    "tapLinear(type, L, map, cube, q, o) ? 0.0 : 1.0; }"));
  writeText(dir / "dan/shadows/pcf.glsl", pcfWith(kTap, kTap.substr(0, kTap.size() - 1)));  // a missing ';'
  fs::create_directories(dir / "eve");
  // A zip with the solution inside a folder of the student's name, as students zip it.
  writeZip(dir / "gus.zip", {{"gus/shadows/pcf.glsl", solution}});
  std::map<std::string, Expected> expected = {{"ana", {"graded", pcfTotal()}}, {"ben", {"graded", -1}},
                                              {"cara", {"graded", -1}},        {"dan", {"did not build", 0}},
                                              {"eve", {"not submitted", 0}},   {"gus", {"graded", pcfTotal()}}};
  if (withSlowOnes) {
    // Reaching into a neighbour's folder: refused by the sandbox, so it does not build.
    writeText(dir / "fay/shadows/pcf.glsl", "#include \"../../ana/shadows/pcf.glsl\"\n");
    // Never ends: stopped by the watchdog in every configuration.
    writeText(dir / "hal/shadows/pcf.glsl",
              pcfWith(kTap,
                      "{ float s = 0.5; for (int k = 0; k >= 0; ++k) { s = fract(sin(s * 1.37) * 43758.5); "
                      "s = fract(sin(s * 1.91) * 43758.5); s = fract(sin(s * 2.3) * 43758.5); } lit += s; }"));
    expected["fay"] = {"did not build", 0};
    expected["hal"] = {"stopped by the watchdog", 0};
  }
  return expected;
}

struct Ran {
  int exitCode = -1;
  std::string output;
};

Ran runShadelab(const std::string& args, const std::string& env = "") {
  static int runs = 0;  // tests run side by side in processes of their own: the pid keeps their logs apart
  const fs::path log = fs::path(SHADELAB_TEST_OUT) / "grade-class" /
                       ("run-" + std::to_string(getpid()) + "-" + std::to_string(++runs) + ".log");
  fs::create_directories(log.parent_path());
  const int status = std::system((env + " " + SHADELAB_BINARY + " " + args + " > '" + log.string() + "' 2>&1").c_str());
  Ran r{WIFEXITED(status) ? WEXITSTATUS(status) : -1, readText(log)};
  fs::remove(log);
  return r;
}

// The gradebook's rows by student: {status, score}.
std::map<std::string, std::pair<std::string, double>> gradebook(const fs::path& out) {
  std::map<std::string, std::pair<std::string, double>> rows;
  std::istringstream in(readText(out / "gradebook.csv"));
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line.rfind("student,exercise,status,score,total,percent,passed,", 0), 0u) << line;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::stringstream s(line);
    for (std::string cell; std::getline(s, cell, ',');) cells.push_back(cell);
    if (cells.size() >= 4) rows[cells[0]] = {cells[2], std::atof(cells[3].c_str())};
  }
  return rows;
}

int fromCache(const std::string& output) {
  int total = 0, cached = -1;
  const size_t at = output.find("solutions: ");
  if (at == std::string::npos ||
      std::sscanf(output.c_str() + at, "solutions: %d configurations, %d from the cache", &total, &cached) != 2)
    return -1;
  return cached;
}

}  // namespace

TEST(GradeClass, EverySubmissionGetsTheRightRowAndTheClassPageShowsTheMisses) {
  const fs::path root = scratch("whole"), cls = root / "class", out = root / "out";
  const auto expected = makeClass(cls, true);
  const Ran r =
      runShadelab("grade --class '" + cls.string() + "' --exercise shadows/pcf --jobs 2 --watchdog 8 --out '" +
                  out.string() + "' --cache '" + (root / "cache").string() + "'");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  const auto rows = gradebook(out);
  ASSERT_EQ(rows.size(), expected.size()) << r.output;
  for (auto& [student, want] : expected) {
    ASSERT_TRUE(rows.count(student)) << student << " has no row\n" << r.output;
    EXPECT_EQ(rows.at(student).first, want.status) << student;
    if (want.score >= 0)
      EXPECT_DOUBLE_EQ(rows.at(student).second, want.score) << student;
    else
      EXPECT_LT(rows.at(student).second, 0.7 * pcfTotal()) << student;
    EXPECT_TRUE(fs::exists(out / "students" / student / "report.html")) << student;
  }
  // The bias of the wrong sign loses the acne check and keeps the shadows, and is named first.
  const std::string cara = readText(out / "students/cara/report.json");
  EXPECT_NE(cara.find("sign of the bias"), std::string::npos);
  EXPECT_NE(cara.find("\"mistake\": \"bias-sign\""), std::string::npos) << cara;
  EXPECT_EQ(readText(out / "students/ana/report.json").find("\"diagnosis\""), std::string::npos)
      << "full marks: no diagnosis";
  // The neighbour's file is never read, so never quoted: not in the report, not on the page.
  const std::string fay = readText(out / "students/fay/report.json");
  EXPECT_NE(fay.find(kSandboxRule), std::string::npos) << fay;
  EXPECT_EQ(fay.find("tapCompare"), std::string::npos) << "quotes ana's solution";
  const std::string page = readText(out / "class.html");
  EXPECT_NE(page.find("missed by"), std::string::npos);
  // Students counted per diagnosis: cara's mistake, ben's untouched starter.
  EXPECT_NE(page.find("<h3>Diagnoses</h3>"), std::string::npos);
  EXPECT_NE(page.find("<td>1 student</td><td class='diag'>The bias has the wrong sign"), std::string::npos);
  EXPECT_NE(page.find("<td class='diag'>Your frames are the starter's"), std::string::npos);
  EXPECT_NE(page.find("check the sign of the bias"), std::string::npos) << "the acne check's hint";
  EXPECT_NE(page.find("data:image/png;base64,"), std::string::npos) << "the misses' images are embedded";
  EXPECT_NE(page.find("stopped by the watchdog"), std::string::npos);
  // The class folder is only read; the unpacked zip is gone.
  EXPECT_FALSE(fs::exists(out / "unpacked"));
  EXPECT_EQ(readText(cls / "ana/shadows/pcf.glsl"), readText(builtinShaderDir() / "shadows/pcf.glsl"));
}

TEST(GradeClass, ShardsMergedGiveTheSameGradebookAndPageAsOneRun) {
  const fs::path root = scratch("shards"), cls = root / "class", cache = root / "cache";
  makeClass(cls, false);
  const std::string common = " --exercise shadows/pcf --cache '" + cache.string() + "' --class '" + cls.string() + "'";
  const Ran whole = runShadelab("grade" + common + " --out '" + (root / "whole").string() + "'");
  ASSERT_EQ(whole.exitCode, 0) << whole.output;
  for (int i = 1; i <= 2; ++i) {
    const Ran shard = runShadelab("grade" + common + " --shard " + std::to_string(i) + "/2 --out '" +
                                  (root / ("shard" + std::to_string(i))).string() + "'");
    ASSERT_EQ(shard.exitCode, 0) << shard.output;
    EXPECT_NE(shard.output.find("grading 3 of 6 submissions"), std::string::npos) << shard.output;
  }
  // A shard left out is named, and nothing is written.
  const Ran partial =
      runShadelab("grade merge '" + (root / "shard1").string() + "' --out '" + (root / "partial").string() + "'");
  EXPECT_EQ(partial.exitCode, 2);
  EXPECT_NE(partial.output.find("shard 2 of 2 is missing"), std::string::npos) << partial.output;
  EXPECT_FALSE(fs::exists(root / "partial" / "gradebook.csv"));

  const Ran merged = runShadelab("grade merge '" + (root / "shard2").string() + "' '" + (root / "shard1").string() +
                                 "' --out '" + (root / "merged").string() + "'");
  ASSERT_EQ(merged.exitCode, 0) << merged.output;
  for (const char* file : {"gradebook.csv", "class.html", "class.json"})
    EXPECT_EQ(readText(root / "merged" / file), readText(root / "whole" / file)) << file << " differs";
  EXPECT_EQ(gradebook(root / "merged").size(), 6u);
  EXPECT_TRUE(fs::exists(root / "merged/students/gus/report.html"));
  // Nothing is overwritten.
  const Ran again = runShadelab("grade merge '" + (root / "shard1").string() + "' '" + (root / "shard2").string() +
                                "' --out '" + (root / "merged").string() + "'");
  EXPECT_EQ(again.exitCode, 2);
  EXPECT_NE(again.output.find("nothing is overwritten"), std::string::npos) << again.output;
}

TEST(GradeClass, ASecondRunTakesTheSolutionsFromTheCacheAndAChangedBuiltInFileMissesIt) {
  const fs::path root = scratch("cache"), cls = root / "class", cache = root / "cache";
  writeText(cls / "ana/shadows/pcf.glsl", readText(builtinShaderDir() / "shadows/pcf.glsl"));
  // The built-in shaders and exercises, copied so that they can be changed.
  fs::copy(builtinShaderDir(), root / "shaders", fs::copy_options::recursive);
  fs::copy(builtinExercisesRoot(), root / "exercises", fs::copy_options::recursive);
  const std::string env = "SHADELAB_SHADERS='" + (root / "shaders").string() + "' SHADELAB_EXERCISES='" +
                          (root / "exercises").string() + "'";
  int n = 0;
  const auto run = [&] {
    const Ran r = runShadelab("grade --class '" + cls.string() + "' --exercise shadows/pcf --cache '" + cache.string() +
                                  "' --out '" + (root / ("out" + std::to_string(++n))).string() + "'",
                              env);
    EXPECT_EQ(r.exitCode, 0) << r.output;
    const std::string points = std::to_string(int(pcfTotal()));
    EXPECT_NE(
        r.output.find("ana                      shadows/pcf               " + points + " / " + points + "  graded"),
        std::string::npos)
        << r.output;
    return fromCache(r.output);
  };
  EXPECT_EQ(run(), 0) << "a cold cache";
  const int configurations = int(pcfConfigurations());
  EXPECT_EQ(run(), configurations) << "every configuration from the cache";
  // A comment added to a built-in file the exercise does not even use: every entry misses.
  writeText(root / "shaders/common/lighting.glsl", readText(root / "shaders/common/lighting.glsl") + "\n// changed\n");
  EXPECT_EQ(run(), 0) << "a changed built-in shader file";
  EXPECT_EQ(run(), configurations);
  const fs::path rubric = root / "exercises/shadows/pcf/rubric.json";
  writeText(rubric, readText(rubric) + "\n");
  EXPECT_EQ(run(), 0) << "a changed rubric";
  // One student's grade uses the cache too.
  const Ran one = runShadelab("grade --exercise shadows/pcf --shaders '" + (cls / "ana").string() + "' --cache '" +
                                  cache.string() + "' --out '" + (root / "one").string() + "'",
                              env);
  EXPECT_EQ(one.exitCode, 0) << one.output;
  EXPECT_NE(one.output.find("solutions: " + std::to_string(configurations) + " of " + std::to_string(configurations) +
                            " configurations from the cache"),
            std::string::npos)
      << one.output;
  // A damaged entry is a miss, not an error.
  for (auto& e : fs::directory_iterator(cache)) fs::resize_file(e.path(), fs::file_size(e.path()) / 2);
  EXPECT_EQ(run(), 0) << "damaged entries";
}

TEST(GradeClass, AZipIsUnpackedOnlyInsideItsFolder) {
  const fs::path root = scratch("zips");
  const auto refused = [&](const std::string& name, const std::map<std::string, std::string>& files,
                           const ZipLimits& limits = {}) {
    const fs::path zip = root / (name + ".zip");
    writeZip(zip, files);
    const std::string e = unpackZip(zip, root / ("unpacked-" + name), limits);
    EXPECT_FALSE(fs::exists(root / "escaped.glsl")) << name;
    return e;
  };
  EXPECT_NE(refused("dotdot", {{"../escaped.glsl", "x"}}).find("would land outside the submission"), std::string::npos);
  EXPECT_NE(refused("absolute", {{"/tmp/escaped.glsl", "x"}}).find("would land outside"), std::string::npos);
  EXPECT_NE(refused("backslash", {{"a\\..\\..\\escaped.glsl", "x"}}).find("would land outside"), std::string::npos);
  ZipLimits small;
  small.fileBytes = 1000;
  EXPECT_NE(refused("big", {{"shadows/pcf.glsl", std::string(5000, ' ')}}, small).find("unpacks to more than"),
            std::string::npos);
  small.entries = 2;
  EXPECT_NE(refused("many", {{"a", "1"}, {"b", "2"}, {"c", "3"}}, small).find("at most 2"), std::string::npos);
  writeText(root / "notazip.zip", "PK but not really");
  EXPECT_NE(unpackZip(root / "notazip.zip", root / "unpacked-notazip").find("not a zip archive"), std::string::npos);
  // A symbolic link stored in the zip (Unix attributes) is refused.
  {
    const fs::path zip = root / "link.zip";
    int error = 0;
    zip_t* z = zip_open(zip.c_str(), ZIP_CREATE | ZIP_TRUNCATE, &error);
    ASSERT_NE(z, nullptr);
    static const char target[] = "/etc/os-release";
    const zip_int64_t i = zip_file_add(z, "shadows/pcf.glsl", zip_source_buffer(z, target, sizeof target - 1, 0), 0);
    ASSERT_GE(i, 0);
    ASSERT_EQ(zip_file_set_external_attributes(z, zip_uint64_t(i), 0, ZIP_OPSYS_UNIX, (0120777u) << 16), 0);
    ASSERT_EQ(zip_close(z), 0);
    EXPECT_NE(unpackZip(zip, root / "unpacked-link").find("symbolic link"), std::string::npos);
  }
  // A good one: its files, read-only; the folder a student zipped around them is looked through.
  writeZip(root / "good.zip", {{"ivy/shadows/pcf.glsl", "// mine\n"}, {"ivy/notes.txt", "hello"}});
  ASSERT_EQ(unpackZip(root / "good.zip", root / "unpacked-good"), "");
  EXPECT_EQ(readText(root / "unpacked-good/ivy/shadows/pcf.glsl"), "// mine\n");
  EXPECT_EQ(fs::status(root / "unpacked-good/ivy/shadows/pcf.glsl").permissions() & fs::perms::owner_write,
            fs::perms::none);
  EXPECT_EQ(shaderRootOf(root / "unpacked-good"), root / "unpacked-good/ivy");
  // A folder holding only "shadows/" is the shader tree itself.
  writeText(root / "plain/shadows/pcf.glsl", "// mine\n");
  EXPECT_EQ(shaderRootOf(root / "plain"), root / "plain");
  removeUnpacked(root / "unpacked-good");
  EXPECT_FALSE(fs::exists(root / "unpacked-good"));
}

// What a student downloads from the in-app editor ("Download my shaders", a stored zip written by
// util/zip_writer) is a submission grade --class takes: libzip reads it back byte for byte.
TEST(GradeClass, TheEditorsDownloadIsASubmission) {
  const fs::path root = scratch("download");
  const std::string pcf = readText(builtinShaderDir() / "shadows/pcf.glsl");
  writeText(root / "ana.zip", storedZip({{"shadows/pcf.glsl", pcf}, {"common/notes.txt", ""}}));
  ASSERT_EQ(unpackZip(root / "ana.zip", root / "unpacked"), "");
  EXPECT_EQ(readText(root / "unpacked/shadows/pcf.glsl"), pcf);
  EXPECT_TRUE(fs::exists(root / "unpacked/common/notes.txt"));
  EXPECT_EQ(shaderRootOf(root / "unpacked"), root / "unpacked");
}

TEST(GradeClass, BadArgumentsAreNamed) {
  const fs::path root = scratch("args");
  fs::create_directories(root / "empty");
  const Ran none = runShadelab("grade --class '" + (root / "empty").string() + "' --exercise shadows/pcf --out '" +
                               (root / "o").string() + "'");
  EXPECT_EQ(none.exitCode, 2);
  EXPECT_NE(none.output.find("holds no submissions"), std::string::npos) << none.output;
  writeText(root / "twice/ana/shadows/pcf.glsl", "//\n");
  writeZip(root / "twice/ana.zip", {{"shadows/pcf.glsl", "//\n"}});
  const Ran twice = runShadelab("grade --class '" + (root / "twice").string() + "' --exercise shadows/pcf --out '" +
                                (root / "o").string() + "'");
  EXPECT_EQ(twice.exitCode, 2);
  EXPECT_NE(twice.output.find("two submissions are named 'ana'"), std::string::npos) << twice.output;
  writeText(root / "one/ana/shadows/pcf.glsl", "//\n");
  const Ran inside = runShadelab("grade --class '" + (root / "one").string() + "' --exercise shadows/pcf --out '" +
                                 (root / "one/report").string() + "'");
  EXPECT_EQ(inside.exitCode, 2);
  EXPECT_NE(inside.output.find("only ever read"), std::string::npos) << inside.output;
  for (const char* bad : {"0/2", "3/2", "1/0", "a/b", "1/2x"}) {
    const Ran shard = runShadelab(std::string("grade --class '") + (root / "twice").string() +
                                  "' --exercise shadows/pcf --shard " + bad);
    EXPECT_EQ(shard.exitCode, 2) << bad << ": grade exits 2 when it cannot grade";
    EXPECT_NE(shard.output.find("--shard: '" + std::string(bad) + "' is not i/n"), std::string::npos) << shard.output;
  }
}

// --all over a class of two: every exercise's starter in one folder (each below 30 %, compiling and
// drawing beside the other exercises' starters), and the seeded mistakes of tests/grade in one
// folder, each failing the check meant to catch it. The lab's own shaders at full marks, and each
// starter alone, are every exercise's `exercise check` (grade.exercise_check.*).
TEST(GradeClass, EveryExerciseGradesTheStartersTogetherAndTheSeededMistakes) {
  const fs::path root = scratch("all"), cls = root / "class", out = root / "out";
  fs::create_directories(cls);
  const std::vector<std::string> ids = listExercises();
  for (auto& id : ids) {
    Exercise ex;
    ASSERT_EQ(loadExercise(id, ex), "");
    fs::copy(ex.dir / "starter", cls / "starters", fs::copy_options::recursive | fs::copy_options::overwrite_existing);
  }
  struct Mistake {
    std::string file, find, replace, exercise, check;
  };
  const std::vector<Mistake> mistakes = {
      {"common/specular.glsl", "max(dot(N, safeNormalize(L + V, N)), 0.0)", "max(dot(N, L + V), 0.0)",
       "shading/blinn-phong", "highlight"},
      {"shadows/pcf.glsl", kTap,
       "{ vec2 o = vec2(i, j) - 0.5 * float(PCF_SIZE - 1); lit += receiverDepth(type, L, q, o) + q.bias > "
       "tapLinear(type, L, map, cube, q, o) ? 0.0 : 1.0; }",
       "shadows/pcf", "no acne"},
      {"surface/bump.glsl", "return normalize(vec3(-slope, 1.0));", "return normalize(vec3(slope, 1.0));",
       "surface/bump", "shaded relief"},
      {"filtering/bilinear.glsl",
       "vec2 p = fract(uv) * vec2(levelSize(s, level)) - 0.5;  // texel centres at whole numbers",
       "vec2 p = fract(uv) * vec2(levelSize(s, level));", "filtering/bilinear", "smooth ramps between texels"},
  };
  for (auto& m : mistakes) writeText(cls / "mistakes" / m.file, labFileWith(m.file, m.find, m.replace));

  // The suite's shared solution cache ($SHADELAB_CACHE): each exercise's solution and mistakes are
  // drawn once in the suite, here or by its `exercise check`.
  const Ran r = runShadelab("grade --class '" + cls.string() + "' --all --jobs 2 --out '" + out.string() + "'");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::map<std::pair<std::string, std::string>, nlohmann::json> rows;  // (student, exercise) -> its report entry
  for (const char* student : {"starters", "mistakes"}) {
    const nlohmann::json report =
        nlohmann::json::parse(readText(out / "students" / student / "report.json"), nullptr, false);
    ASSERT_TRUE(report.is_object()) << student;
    for (auto& e : report["exercises"]) rows[{student, e["id"].get<std::string>()}] = e;
  }
  for (auto& id : ids) {
    const nlohmann::json& starter = rows[std::pair<std::string, std::string>("starters", id)];
    EXPECT_EQ(starter["status"], "graded") << id;
    EXPECT_LT(starter["percent"].get<double>(), 30.0) << id;
    for (auto& c : starter["checks"]) {  // the starter compiles and draws: every check has a number
      EXPECT_TRUE(c["errors"].empty()) << id << ": " << c["errors"];
      EXPECT_TRUE(c["value"].is_number()) << id << ": " << c["check"];
    }
  }
  for (auto& m : mistakes) {
    const nlohmann::json& e = rows[{"mistakes", m.exercise}];
    bool found = false;
    for (auto& c : e["checks"])
      if (c["check"] == m.check) {
        found = true;
        EXPECT_NE(c["result"], "PASS") << m.exercise << ": " << m.check;
      }
    EXPECT_TRUE(found) << m.exercise << " has no check '" << m.check << "'";
  }
  // The gradebook: a row per student and exercise.
  std::istringstream book(readText(out / "gradebook.csv"));
  size_t lines = 0;
  for (std::string line; std::getline(book, line);) ++lines;
  EXPECT_EQ(lines, 1 + 2 * ids.size());
}

// `shadelab grade` end to end, through the real binary: seeded mistakes fail the check meant to
// catch them with a message that points at the cause (every exercise's solution and starter are
// graded in class_test.cpp, its listed mistakes in mistakes_test.cpp), an endless loop is stopped and grading goes on,
// a syntax error is reported at the student's file:line, and the student's folder is never written.
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "app/grade/rubric.h"
#include "app/shader/preprocessor.h"
#include "test_files.h"

using namespace shadelab;
namespace fs = std::filesystem;

namespace {

struct Graded {
  int exitCode = -1;
  std::string output;  // stdout and stderr
  nlohmann::json report;
  const nlohmann::json& check(const std::string& name) const {
    for (auto& c : report["exercises"][0]["checks"])
      if (c["check"] == name) return c;
    throw std::runtime_error("no check '" + name + "' in the report");
  }
  double percent() const { return report["exercises"][0]["percent"].get<double>(); }
  const nlohmann::json& exercise() const { return report["exercises"][0]; }
};

using test::slug;

fs::path scratch(const std::string& name) { return test::freshFolder("grade", name); }

// Where a test's report goes, beside its student folder (grade() clears it first).
fs::path reportDir(const std::string& name) { return fs::path(SHADELAB_TEST_OUT) / "grade" / name / "report"; }

Graded grade(const std::string& exercise, const fs::path& shaders, const fs::path& out, const std::string& extra = "") {
  const fs::path log =
      fs::path(SHADELAB_TEST_OUT) / "grade" / (slug(out.string()) + ".log");  // outside any student folder
  fs::remove_all(out);
  const std::string cmd = std::string(SHADELAB_BINARY) + " grade --exercise " + exercise + " --shaders '" +
                          shaders.string() + "' --out '" + out.string() + "' " + extra + " > '" + log.string() +
                          "' 2>&1";
  Graded g;
  const int status = std::system(cmd.c_str());
  g.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream in(log);
  std::stringstream s;
  s << in.rdbuf();
  g.output = s.str();
  std::ifstream report(out / "report.json");
  if (report) g.report = nlohmann::json::parse(report, nullptr, false);
  return g;
}

// A student folder holding the lab's `file` with `find` (which must occur exactly once, so a
// change to the lab's shader cannot silently turn the mistake into a no-op) replaced.
fs::path seeded(const std::string& name, const std::string& file, const std::string& find, const std::string& replace) {
  std::ifstream in(builtinShaderDir() / file);
  std::stringstream s;
  s << in.rdbuf();
  std::string text = s.str();
  const size_t at = text.find(find);
  EXPECT_NE(at, std::string::npos) << file << " no longer holds: " << find;
  EXPECT_EQ(text.find(find, at + 1), std::string::npos) << file << " holds it twice: " << find;
  if (at != std::string::npos) text.replace(at, find.size(), replace);
  const fs::path dir = scratch(name) / "student";
  fs::create_directories((dir / file).parent_path());
  std::ofstream(dir / file) << text;
  return dir;
}

}  // namespace

TEST(GradeMistakes, AnUnnormalisedHalfVectorFailsTheHighlight) {
  const fs::path student = seeded("half-vector", "common/specular.glsl", "max(dot(N, safeNormalize(L + V, N)), 0.0)",
                                  "max(dot(N, L + V), 0.0)");
  const Graded g = grade("shading/blinn-phong", student, reportDir("half-vector"));
  ASSERT_TRUE(g.report.is_object()) << g.output;
  EXPECT_EQ(g.check("highlight")["result"], "FAIL");
  EXPECT_EQ(g.exercise()["mistake"], "half-vector-not-normalised") << g.output;
  EXPECT_NE(g.exercise()["diagnosis"].get<std::string>().find("not normalised"), std::string::npos);
  // The diagnosis is the first line under the exercise, on the terminal and in report.md.
  EXPECT_NE(g.output.find("statement.md)\n  diagnosis: The half vector is not normalised"), std::string::npos)
      << g.output;
}

// A mistake no rubric lists, in the third of four lines: the trace of the student's own function
// beside the solution's names that line, what matches up to it, and how its value relates to the
// solution's result, never the solution's code.
TEST(GradeMistakes, TheLineWhereAStudentsValuesPartIsNamedFromTheirOwnCode) {
  const fs::path student =
      seeded("traced", "common/specular.glsl", "  return max(dot(N, safeNormalize(L + V, N)), 0.0);\n",
             "  vec3 H = safeNormalize(L + V, N);\n"
             "  float c = dot(N, H);\n"
             "  float s = max(c, 0.0) * 2.0;\n"
             "  return s;\n");
  const Graded g = grade("shading/blinn-phong", student, reportDir("traced"));
  ASSERT_TRUE(g.report.is_object()) << g.output;
  EXPECT_EQ(g.exercise()["explanation"], "line:12") << g.output;
  const std::string said = g.exercise()["diagnosis"].get<std::string>();
  EXPECT_EQ(said.rfind("Line 12 of common/specular.glsl (`s`): your values up to this line match the solution's", 0),
            0u)
      << said;
  EXPECT_NE(said.find("`max(c, 0.0)`, which it is made of, matches"), std::string::npos) << said;
  EXPECT_NE(said.find("It is 2 times the solution's result."), std::string::npos) << said;
  EXPECT_EQ(said.find("dot(N, safeNormalize"), std::string::npos) << "the solution's code is never shown: " << said;
  // The trace travels in the report with the probe's frame.
  bool traced = false;
  for (auto& f : g.exercise()["frames"])
    if (f.contains("trace")) traced = f["trace"]["line"] == 12;
  EXPECT_TRUE(traced) << g.exercise()["frames"].dump();
}

// A function no probe holds (PCF takes the lab's maps and structs) is traced in the lab's own draw,
// at the pixel where the student's frame differs most: the grid centred a whole kernel off is one
// slip of the solution (a constant changed), named first, with the line of the change traced after
// it, and the trace travels in the report's frame with its pixel.
TEST(GradeMistakes, AFunctionNoProbeHoldsIsTracedInTheLabsDraw) {
  const fs::path student = seeded("traced-in-draw", "shadows/pcf.glsl", "vec2(i, j) - 0.5 * float(PCF_SIZE - 1));",
                                  "vec2(i, j) - float(PCF_SIZE - 1));");
  const Graded g = grade("shadows/pcf", student, reportDir("traced-in-draw"));
  ASSERT_TRUE(g.report.is_object()) << g.output;
  EXPECT_EQ(g.exercise()["explanation"], "slip:constant") << g.output;
  const std::string said = g.exercise()["diagnosis"].get<std::string>();
  EXPECT_NE(said.find("Traced line by line in the lab's draw: Line 9 of shadows/pcf.glsl"), std::string::npos) << said;
  bool traced = false;
  for (auto& f : g.exercise()["frames"])
    if (f.contains("trace") && f["trace"]["line"] == 9) traced = f["trace"]["pixel"][0].get<int>() >= 0;
  EXPECT_TRUE(traced) << g.exercise()["frames"].dump();
}

TEST(GradeMistakes, ABiasWithTheWrongSignFailsTheAcneCheckOnly) {
  const fs::path student = seeded(
      "bias-sign", "shadows/pcf.glsl",
      "lit += tapCompare(type, L, map, cube, q, vec2(i, j) - 0.5 * float(PCF_SIZE - 1));",
      "{\n      vec2 o = vec2(i, j) - 0.5 * float(PCF_SIZE - 1);\n"
      "      lit += receiverDepth(type, L, q, o) + q.bias > tapLinear(type, L, map, cube, q, o) ? 0.0 : 1.0;\n    }");
  const Graded g = grade("shadows/pcf", student, reportDir("bias-sign"));
  ASSERT_TRUE(g.report.is_object()) << g.output;
  EXPECT_EQ(g.check("no acne")["result"], "FAIL");
  EXPECT_NE(g.check("no acne")["message"].get<std::string>().find("sign of the bias"), std::string::npos);
  EXPECT_EQ(g.check("shadow where the truth has one")["result"], "PASS");
}

TEST(GradeMistakes, TapsInTextureCoordinatesInsteadOfTexelsFailTheSoftEdge) {
  const fs::path student = seeded("tap-space", "shadows/pcf.glsl", "vec2(i, j) - 0.5 * float(PCF_SIZE - 1));",
                                  "(vec2(i, j) - 0.5 * float(PCF_SIZE - 1)) * q.texel);");
  const Graded g = grade("shadows/pcf", student, reportDir("tap-space"));
  ASSERT_TRUE(g.report.is_object()) << g.output;
  EXPECT_EQ(g.check("soft edge")["result"], "FAIL");
  EXPECT_EQ(g.check("penumbra width")["result"], "FAIL") << "a hard edge";
  EXPECT_EQ(g.exercise()["mistake"], "offsets-in-uv") << g.output;
  EXPECT_NE(g.exercise()["diagnosis"].get<std::string>().find("take texels"), std::string::npos);
  EXPECT_EQ(g.check("no acne")["result"], "PASS");
  EXPECT_EQ(g.check("shadow where the truth has one")["result"], "PASS");
}

TEST(GradeMistakes, ABumpNormalLeaningWithTheSlopeFailsTheRelief) {
  const fs::path student = seeded("bump-sign", "surface/bump.glsl", "return normalize(vec3(-slope, 1.0));",
                                  "return normalize(vec3(slope, 1.0));");
  const Graded g = grade("surface/bump", student, reportDir("bump-sign"));
  ASSERT_TRUE(g.report.is_object()) << g.output;
  EXPECT_EQ(g.check("shaded relief")["result"], "FAIL");
  EXPECT_NE(g.check("shaded relief")["message"].get<std::string>().find("sign error"), std::string::npos);
}

TEST(GradeMistakes, BilinearWithoutTheHalfTexelShiftFailsTheMagnifiedRamps) {
  const fs::path student =
      seeded("half-texel", "filtering/bilinear.glsl",
             "vec2 p = fract(uv) * vec2(levelSize(s, level)) - 0.5;  // texel centres at whole numbers",
             "vec2 p = fract(uv) * vec2(levelSize(s, level));");
  const Graded g = grade("filtering/bilinear", student, reportDir("half-texel"));
  ASSERT_TRUE(g.report.is_object()) << g.output;
  EXPECT_NE(g.check("smooth ramps between texels")["result"], "PASS");
  EXPECT_NE(g.check("smooth ramps between texels")["message"].get<std::string>().find("half a texel"),
            std::string::npos);
}

TEST(GradeFailures, AnEndlessLoopIsStoppedByTheWatchdogAndGradingGoesOn) {
  // llvmpipe stops any one loop after 65535 iterations; 8 transcendental steps per iteration for
  // every fragment of two lights still take far longer than the watchdog's 8 s, while a few
  // hundred vertices take a fraction of a second. On a GPU it would never end.
  std::string body = "float s = dot(N, L);\n  for (int i = 0; i >= 0; ++i) {  // never ends\n";
  for (int k = 0; k < 8; ++k) body += "    s = fract(sin(s * 1.37 + " + std::to_string(k) + ".0) * 43758.5);\n";
  body += "  }\n  return s;";
  const fs::path student =
      seeded("endless", "common/specular.glsl", "return max(dot(N, safeNormalize(L + V, N)), 0.0);", body);
  // 8 s: the per-fragment configurations need minutes; the per-vertex one a fraction of a second
  // alone, a few on a loaded machine or in the sanitizer build.
  const Graded g = grade("shading/blinn-phong", student, reportDir("endless"), "--watchdog 8");
  ASSERT_TRUE(g.report.is_object()) << g.output;
  const auto& stopped = g.check("highlight");
  EXPECT_EQ(stopped["result"], "FAIL");
  EXPECT_NE(stopped["message"].get<std::string>().find("stopped by the watchdog after 8 s"), std::string::npos)
      << stopped["message"];
  // The per-vertex configuration runs the loop for a few hundred vertices only: it finishes and is scored.
  EXPECT_TRUE(g.check("per-vertex highlight")["value"].is_number()) << g.output;
  EXPECT_EQ(g.exitCode, 1);
}

TEST(GradeFailures, ASyntaxErrorIsReportedAtTheStudentsFileAndLine) {
  const fs::path student = seeded("syntax", "common/specular.glsl", "return max(dot(N, safeNormalize(L + V, N)), 0.0);",
                                  "return max(dot(N, safeNormalize(L + V, N)), 0.0)");
  const Graded g = grade("shading/blinn-phong", student, reportDir("syntax"));
  ASSERT_TRUE(g.report.is_object()) << g.output;
  const std::string where = (student / "common/specular.glsl").string() + ":";
  EXPECT_NE(g.output.find(where), std::string::npos) << g.output;
  EXPECT_NE(g.output.find("error"), std::string::npos);
  EXPECT_NE(g.output.find("\n    "), std::string::npos) << "the source line and its caret";
  EXPECT_NE(g.output.find('^'), std::string::npos);
  // Printed once, though the per-fragment and per-vertex programs both fail on it.
  const size_t first = g.output.find(where);
  EXPECT_EQ(g.output.find(where, first + 1), std::string::npos) << g.output;
  const auto& c = g.check("highlight");
  EXPECT_EQ(c["result"], "FAIL");
  EXPECT_NE(c["message"].get<std::string>().find("did not build: shading/phong: " + where), std::string::npos) << c;
  EXPECT_EQ(g.percent(), 0.0);
}

// A submission that includes a file outside its folder (a system file, a neighbour's solution by
// "..", through a linked folder, or a submitted file that is itself a link to the neighbour's)
// does not build, is told the rule, and neither the output nor any report quotes the file.
TEST(GradeFailures, AnIncludeLeavingTheStudentsFolderIsRefusedAndNeverQuoted) {
  const fs::path classDir = scratch("escape");
  const std::string marker = "NEIGHBOURS_SOLUTION_MARKER";
  const fs::path bob = classDir / "bob" / "common";
  fs::create_directories(bob);
  std::ofstream(bob / "specular.glsl") << "// " << marker << "\n" << marker << " vec3 broken(\n";
  std::ifstream builtin(builtinShaderDir() / "common/specular.glsl");
  std::stringstream specular;
  specular << builtin.rdbuf();

  struct Form {
    std::string name, includeLine, expected;  // the student's first line; what the output must say
  };
  const std::vector<Form> forms = {
      {"absolute", "#include \"/etc/os-release\"", ":1:11: error: " + std::string(kSandboxRule)},
      {"dotdot", "#include \"../../bob/common/specular.glsl\"", ":1:11: error: " + std::string(kSandboxRule)},
      {"linkedfolder", "#include \"borrowed/specular.glsl\"", ":1:11: error: " + std::string(kSandboxRule)},
      {"linkedfile", "", std::string(kSandboxRule) + " (a link leads out of"},
  };
  for (auto& form : forms) {
    const fs::path student = classDir / ("alice_" + form.name);
    fs::create_directories(student / "common");
    if (form.name == "linkedfile") {
      fs::create_symlink(bob / "specular.glsl", student / "common/specular.glsl");
    } else {
      std::ofstream(student / "common/specular.glsl") << form.includeLine << "\n" << specular.str();
      if (form.name == "linkedfolder") fs::create_directory_symlink(bob, student / "common" / "borrowed");
    }
    const fs::path reports = classDir / ("report_" + form.name);
    const Graded g = grade("shading/blinn-phong", student, reports);
    ASSERT_TRUE(g.report.is_object()) << form.name << ": " << g.output;
    EXPECT_NE(g.output.find(form.expected), std::string::npos) << form.name << ": " << g.output;
    EXPECT_EQ(g.percent(), 0.0) << form.name;
    for (const std::string leak : {"PRETTY_NAME", "VERSION_ID", marker.c_str()}) {
      EXPECT_EQ(g.output.find(leak), std::string::npos) << form.name << " leaked " << leak << ": " << g.output;
      for (const char* report : {"report.md", "report.html", "report.json"}) {
        std::ifstream r(reports / report);
        std::stringstream text;
        text << r.rdbuf();
        EXPECT_FALSE(text.str().empty()) << form.name << ": no " << report;
        EXPECT_EQ(text.str().find(leak), std::string::npos) << form.name << ": " << report << " leaked " << leak;
      }
    }
  }
}

TEST(GradeFailures, TheStudentsFolderIsOnlyRead) {
  Exercise ex;
  ASSERT_EQ(loadExercise("shading/blinn-phong", ex), "");
  const fs::path student = scratch("read-only") / "student";
  fs::copy(ex.dir / "starter", student, fs::copy_options::recursive);
  const auto snapshot = [&] {
    std::string s;
    for (auto& e : fs::recursive_directory_iterator(student))
      s += e.path().string() + " " + std::to_string(e.is_regular_file() ? fs::file_size(e.path()) : 0) + " " +
           std::to_string(fs::last_write_time(e.path()).time_since_epoch().count()) + "\n";
    return s;
  };
  const std::string before = snapshot();
  const Graded g = grade("shading/blinn-phong", student, reportDir("read-only"));
  EXPECT_TRUE(g.report.is_object()) << g.output;
  EXPECT_EQ(snapshot(), before);
  // A report inside the graded folder is refused before anything is written.
  const Graded inside = grade("shading/blinn-phong", student, student / "report");
  EXPECT_EQ(inside.exitCode, 2) << inside.output;
  EXPECT_NE(inside.output.find("only ever read"), std::string::npos) << inside.output;
  EXPECT_EQ(snapshot(), before);
}

TEST(GradeFailures, AMissingFileIsNotSubmittedAndScoresNothing) {
  const fs::path empty = scratch("missing") / "student";
  fs::create_directories(empty);
  const Graded g = grade("surface/bump", empty, reportDir("missing"));
  ASSERT_TRUE(g.report.is_object()) << g.output;
  EXPECT_EQ(g.percent(), 0.0);
  EXPECT_EQ(g.report["exercises"][0]["missing_files"][0], "surface/bump.glsl");
  EXPECT_NE(g.output.find("not submitted"), std::string::npos);
}

// What the diagnosis rests on (each rubric's mistakes and correct variants are graded as a class
// by `shadelab exercise check`, a test per exercise in tests/CMakeLists.txt):
// a frame with NaN is named as such where no mistake explains it, a hint whose evidence is missing
// stays silent, and the mistakes' frames live in the solution cache, so a second run draws none.
#include <cstdlib>
#include <fstream>

#include <gtest/gtest.h>
#include <unistd.h>
#include <nlohmann/json.hpp>

#include "app/grade/configuration_frames.h"
#include "app/grade/frame_properties.h"
#include "app/grade/rubric.h"
#include "app/grade/solution_cache.h"
#include "app/shader/preprocessor.h"
#include "test_files.h"

using namespace shadelab;
namespace fs = std::filesystem;

namespace {

using test::readText;
using test::slug;

fs::path scratch(const std::string& name) { return test::freshFolder("grade-mistakes", name); }

// Runs the shadelab binary with `args`; returns its exit code, the output in `output`.
int runShadelab(const std::string& args, std::string& output, const std::string& env = "") {
  const fs::path log = fs::path(SHADELAB_TEST_OUT) / "grade-mistakes" / ("run-" + std::to_string(getpid()) + ".log");
  const int status = std::system((env + " " + SHADELAB_BINARY + " " + args + " > '" + log.string() + "' 2>&1").c_str());
  output = readText(log);
  fs::remove(log);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

nlohmann::json exerciseReport(const fs::path& reportJson) {
  const nlohmann::json j = nlohmann::json::parse(readText(reportJson), nullptr, false);
  return j.is_object() && j.contains("exercises") && !j["exercises"].empty() ? j["exercises"][0] : nlohmann::json();
}

// A submission written as a replacement of the starter's TODO region (a rubric mistake's "body").
Mistake todoBody(const Exercise& ex, const std::string& name, const std::string& body) {
  Mistake m;
  m.name = name;
  m.file = ex.files.front();
  m.body = body;
  return m;
}

}  // namespace

// Where no listed mistake explains the frames, a NaN is named for what it is: an exercise whose
// rubric lists no mistakes, and a highlight that pow()s a negative N.H.
// A highlight without its clamp (and a plain normalize where the lab's is safe): the shading's
// pow() of a negative base makes NaN pixels. No listed mistake is left to explain them; the
// solution's slip that drops the clamp draws the very same frames, NaN included, and is named
// with where the NaN lie.
TEST(Diagnosis, ANanFrameIsExplainedByTheSlipThatMakesItWhereNoMistakeIsListed) {
  const fs::path root = scratch("nan");
  fs::create_directories(root / "exercises/shading");
  fs::copy(builtinExercisesRoot() / "shading", root / "exercises/shading", fs::copy_options::recursive);
  const fs::path rubric = root / "exercises/shading/blinn-phong/rubric.json";
  nlohmann::json r = nlohmann::json::parse(readText(rubric));
  r.erase("mistakes");
  std::ofstream(rubric) << r.dump(2);
  Exercise ex;
  ASSERT_EQ(loadExercise(root / "exercises", "shading/blinn-phong", ex), "");
  ASSERT_EQ(writeMistakeFolder(ex, todoBody(ex, "nan", "  return dot(N, normalize(L + V));"), root / "student"), "");
  std::string output;
  const fs::path cache = root / "cache";
  runShadelab("grade --exercise shading/blinn-phong --shaders '" + (root / "student").string() + "' --out '" +
                  (root / "out").string() + "' --cache '" + cache.string() + "'",
              output, "SHADELAB_EXERCISES='" + (root / "exercises").string() + "'");
  const nlohmann::json e = exerciseReport(root / "out/report.json");
  ASSERT_TRUE(e.is_object()) << output;
  const std::string diagnosis = e.value("diagnosis", "");
  EXPECT_EQ(e.value("explanation", ""), "slip:call-dropped") << diagnosis;
  // The slips were drawn in a second pass and kept with the solution's frames: those that draw
  // differently, at half size (a probe's table whole), none beyond what the mutator makes.
  size_t entries = 0;
  for (auto& entry : fs::directory_iterator(cache)) {
    CachedSolution s;
    ASSERT_TRUE(SolutionCache(cache).load(entry.path().stem().string(), s)) << entry.path();
    ASSERT_TRUE(s.numbers.contains("slips")) << entry.path();
    EXPECT_EQ(s.numbers["slips"].size(), s.slips.size());
    EXPECT_FALSE(s.slips.empty());
    EXPECT_LE(s.slips.size(), solutionSlips(ex).size());
    for (size_t i = 0; i < s.slips.size(); ++i) {
      EXPECT_TRUE(s.slips[i].size == s.frame.size || s.slips[i].size == s.frame.size / 2);
      EXPECT_GT(s.numbers["slips"][i]["separation"].get<double>(), kFramesDiffer);
    }
    ++entries;
  }
  EXPECT_EQ(entries, ex.configurations.size());
  EXPECT_NE(diagnosis.find("a call to max left out"), std::string::npos) << diagnosis;
  EXPECT_NE(diagnosis.find("NaN and Inf included"), std::string::npos) << diagnosis;
  EXPECT_NE(diagnosis.find(" NaN pixels in x "), std::string::npos) << "where the NaN lie: " << diagnosis;
  EXPECT_FALSE(e.contains("mistake"));
  EXPECT_LT(e["percent"].get<double>(), ex.passMark);
}

// The PCF rubric's point-light hint speaks only when the directional configurations pass: offsets
// in texture coordinates are wrong for every light, and that student is not sent to the cube map.
TEST(Diagnosis, AHintWhoseEvidenceIsMissingStaysSilent) {
  Exercise ex;
  ASSERT_EQ(loadExercise("shadows/pcf", ex), "");
  const auto it =
      std::find_if(ex.mistakes.begin(), ex.mistakes.end(), [](const Mistake& m) { return m.name == "offsets-in-uv"; });
  ASSERT_NE(it, ex.mistakes.end());
  const fs::path root = scratch("silent");
  ASSERT_EQ(writeMistakeFolder(ex, *it, root / "student"), "");
  std::string output;
  runShadelab("grade --exercise shadows/pcf --shaders '" + (root / "student").string() + "' --out '" +
                  (root / "out").string() + "'",
              output);
  const nlohmann::json e = exerciseReport(root / "out/report.json");
  ASSERT_TRUE(e.is_object()) << output;
  bool seen = false;
  for (auto& c : e["checks"])
    if (c["check"] == "cube-map taps") {
      seen = true;
      EXPECT_NE(c["result"], "PASS") << "the mistake shows with a point light too";
      EXPECT_EQ(c["message"], "") << "the cube-map hint, with the directional configurations failing";
      EXPECT_FALSE(c["hint"].get<std::string>().empty());
    }
  EXPECT_TRUE(seen);
  EXPECT_EQ(output.find("go round a cube map"), std::string::npos) << output;
}

// The mistakes' frames are drawn with the solution's, once, and kept in its cache entry: a second
// run takes every configuration from the cache and so draws no mistake again.
TEST(Diagnosis, TheCacheHoldsTheMistakesFramesAndASecondRunDrawsNone) {
  Exercise ex;
  ASSERT_EQ(loadExercise("filtering/bilinear", ex), "");
  const fs::path root = scratch("cache"), cache = root / "cache";
  const auto run = [&](const std::string& out) {
    std::string output;
    runShadelab("grade --exercise filtering/bilinear --shaders '" + (ex.dir / "starter").string() + "' --cache '" +
                    cache.string() + "' --out '" + (root / out).string() + "'",
                output);
    return output;
  };
  const std::string n = std::to_string(ex.configurations.size());
  const std::string cold = run("cold");
  EXPECT_NE(cold.find("solutions: 0 of " + n + " configurations from the cache"), std::string::npos) << cold;
  const std::string warm = run("warm");
  EXPECT_NE(warm.find("solutions: " + n + " of " + n + " configurations from the cache"), std::string::npos) << warm;
  EXPECT_EQ(exerciseReport(root / "warm/report.json").value("mistake", ""), "starter") << warm;
  size_t entries = 0;
  for (auto& entry : fs::directory_iterator(cache)) {
    CachedSolution s;
    ASSERT_TRUE(SolutionCache(cache).load(entry.path().stem().string(), s)) << entry.path();
    EXPECT_EQ(s.mistakes.size(), ex.mistakes.size()) << "the starter's and every listed mistake's frame";
    EXPECT_EQ(s.numbers["mistakes"].size(), ex.mistakes.size());
    for (auto& m : s.mistakes) EXPECT_EQ(m.size, s.frame.size);
    // The starter is named as itself: no diagnosis asked for the solution's slips, so none was drawn.
    EXPECT_FALSE(s.numbers.contains("slips"));
    EXPECT_TRUE(s.slips.empty());
    ++entries;
  }
  EXPECT_EQ(entries, ex.configurations.size());
}

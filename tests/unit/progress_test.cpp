// What a student keeps in their folder: each exercise's last Check, and the dated copy a reset
// leaves of their file.
#include <gtest/gtest.h>

#include <unistd.h>

#include <fstream>

#include "app/grade/exercise_check.h"
#include "app/grade/progress.h"
#include "app/util/read_file.h"

using namespace shadelab;
namespace fs = std::filesystem;

namespace {

fs::path freshFolder(const char* name) {
  const fs::path dir = fs::temp_directory_path() / (std::string(name) + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

}  // namespace

TEST(Progress, EachExercisesLastCheckIsKeptAndReadBack) {
  const fs::path folder = freshFolder("shadelab_progress_");
  EXPECT_TRUE(readProgress(folder).empty());
  Progress p;
  ASSERT_EQ(recordProgress(folder, p, "shadows/pcf", 42.5, false), "");
  ASSERT_EQ(recordProgress(folder, p, "shading/blinn-phong", 100.0, true), "");
  ASSERT_EQ(recordProgress(folder, p, "shadows/pcf", 80.0, true), "");  // the last Check wins
  const Progress back = readProgress(folder);
  ASSERT_EQ(back.size(), 2u);
  EXPECT_DOUBLE_EQ(back.at("shadows/pcf").percent, 80.0);
  EXPECT_TRUE(back.at("shadows/pcf").passed);
  EXPECT_EQ(back.at("shading/blinn-phong").when.size(), 16u);  // "2026-11-28 17:20"
  // A file that does not read is no progress, never an error.
  std::ofstream(progressFile(folder), std::ios::trunc) << "{\"exercises\": [1, 2";
  EXPECT_TRUE(readProgress(folder).empty());
  std::ofstream(progressFile(folder), std::ios::trunc) << R"({"exercises": {"a/b": {"percent": "lots"}, "c/d": 3}})";
  EXPECT_TRUE(readProgress(folder).empty());
  fs::remove_all(folder);
}

TEST(Progress, ResetToTheStarterKeepsTheStudentsFileAsADatedCopy) {
  const fs::path folder = freshFolder("shadelab_reset_");
  Exercise ex;
  ASSERT_EQ(loadExercise("shading/blinn-phong", ex), "");
  fs::create_directories(folder / "common");
  std::ofstream(folder / "common/specular.glsl") << "// my work\n";
  std::vector<std::string> kept;
  ASSERT_EQ(resetToStarter(ex, folder, kept), "");
  ASSERT_EQ(kept.size(), 1u);
  EXPECT_EQ(kept[0].rfind("common/specular.kept-", 0), 0u) << kept[0];
  EXPECT_EQ(readWholeFile(folder / kept[0]), "// my work\n");
  EXPECT_EQ(readWholeFile(folder / "common/specular.glsl"), readWholeFile(ex.dir / "starter/common/specular.glsl"));
  fs::remove_all(folder);
}

// The solution cache keeps to its budget: the least recently used entries go first, and reading
// an entry counts as using it.
#include <chrono>
#include <cstdlib>
#include <filesystem>

#include <gtest/gtest.h>

#include "app/grade/configuration_frames.h"
#include "app/grade/solution_cache.h"

using namespace shadelab;
namespace fs = std::filesystem;

namespace {

CachedSolution entryOf(float value) {
  CachedSolution s;
  s.frame.size = {16, 16};
  s.frame.rgba.assign(16 * 16 * 4, value);
  s.numbers = {{"renderer", "test"}};
  return s;
}

// Each store gets a modification time of its own, whatever the file system's resolution.
void age(const fs::path& dir, const std::string& key, int secondsAgo) {
  fs::last_write_time(dir / (key + ".bin"), fs::file_time_type::clock::now() - std::chrono::seconds(secondsAgo));
}

}  // namespace

TEST(SolutionCache, TheLeastRecentlyUsedEntriesGoWhenTheBudgetIsSpent) {
  const fs::path dir = fs::temp_directory_path() / "shadelab-cache-budget-test";
  fs::remove_all(dir);
  const uint64_t oneEntry = 16 * 16 * 4 * sizeof(float) + 200;  // the frame and a little JSON
  const SolutionCache cache(dir, 3 * oneEntry);
  for (const char* key : {"a", "b", "c"}) ASSERT_EQ(cache.store(key, entryOf(0.5f)), "");
  age(dir, "a", 300);
  age(dir, "b", 200);
  age(dir, "c", 100);
  CachedSolution read;
  ASSERT_TRUE(cache.load("a", read));  // used now: b is the oldest
  EXPECT_EQ(read.frame.rgba.front(), 0.5f);
  ASSERT_EQ(cache.store("d", entryOf(0.25f)), "");
  EXPECT_TRUE(fs::exists(dir / "a.bin"));
  EXPECT_FALSE(fs::exists(dir / "b.bin"));
  EXPECT_TRUE(fs::exists(dir / "c.bin"));
  EXPECT_TRUE(cache.load("d", read));
  EXPECT_EQ(read.frame.rgba.front(), 0.25f);
  // A budget smaller than one entry keeps the entry just stored, and nothing else.
  const SolutionCache tiny(dir, 1);
  ASSERT_EQ(tiny.store("e", entryOf(1.0f)), "");
  size_t left = 0;
  for (auto& f : fs::directory_iterator(dir)) left += f.path().extension() == ".bin";
  EXPECT_EQ(left, 1u);
  EXPECT_TRUE(fs::exists(dir / "e.bin"));
  fs::remove_all(dir);
}

TEST(SolutionCache, TheBudgetComesFromTheEnvironmentOrIsFourGiB) {
  unsetenv("SHADELAB_CACHE_MB");
  EXPECT_EQ(SolutionCache::defaultBudgetBytes(), 4096ull << 20);
  setenv("SHADELAB_CACHE_MB", "100", 1);
  EXPECT_EQ(SolutionCache::defaultBudgetBytes(), 100ull << 20);
  for (const char* bad : {"0", "-5", "lots", "12MB", ""}) {
    setenv("SHADELAB_CACHE_MB", bad, 1);
    EXPECT_EQ(SolutionCache::defaultBudgetBytes(), 4096ull << 20) << bad;
  }
  unsetenv("SHADELAB_CACHE_MB");
}

// Frames kept under a key of their own (the solution at other settings) read back whole, and an
// entry of the other kind, or a cut-short one, is a miss.
TEST(SolutionCache, FramesKeptApartReadBackAndNeverAsASolution) {
  const fs::path dir = fs::temp_directory_path() / "shadelab-cache-frames-test";
  fs::remove_all(dir);
  const SolutionCache cache(dir);
  SettingFrames frames;
  frames.tried = {{0, ""}, {2, "0.5"}};
  frames.frames = {entryOf(0.25f).frame, entryOf(0.75f).frame};
  ASSERT_EQ(cache.store("settings", keptSettingFrames(frames)), "");
  CachedFrames kept;
  ASSERT_TRUE(cache.load("settings", kept));
  SettingFrames back;
  ASSERT_TRUE(settingFramesFromKept(kept, back));
  ASSERT_EQ(back.tried.size(), 2u);
  EXPECT_EQ(back.tried[1].setting, 2u);
  EXPECT_EQ(back.tried[1].value, "0.5");
  EXPECT_EQ(back.tried[0].value, "");
  ASSERT_EQ(back.frames.size(), 2u);
  EXPECT_EQ(back.frames[1].rgba.back(), 0.75f);

  CachedSolution notASolution;
  EXPECT_FALSE(cache.load("settings", notASolution));
  ASSERT_EQ(cache.store("solution", entryOf(1.0f)), "");
  EXPECT_FALSE(cache.load("solution", kept));
  // A set whose list and frames disagree is not taken for one.
  kept.frames.pop_back();
  EXPECT_FALSE(settingFramesFromKept(kept, back));
  // Cut short: a miss, never an error.
  fs::resize_file(dir / "settings.bin", fs::file_size(dir / "settings.bin") - 5);
  EXPECT_FALSE(cache.load("settings", kept));
  fs::remove_all(dir);
}

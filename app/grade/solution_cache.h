// What grading renders with the built-in shaders, kept between runs: for one rubric configuration,
// the solution's frame, the lab's ground truths and the solution's numbers against them, and the
// frame of every mistake the rubric lists (the solution with that one change), and of every slip
// (the solution changed in one place, grade/mutants.h) that draws differently. A class of
// 500 students needs them once, not 500 times.
//
// An entry is named by a key over everything that could change it: the contents of every built-in
// shader file, the exercise's rubric, the configuration's place in it, the program that renders
// (the executable's bytes: a change to a lab's code changes its truth) and the renderer (GL
// vendor, renderer and version). Change any of them and the old entry is simply never asked for.
//
// Entries are written under a temporary name and renamed into place, so processes grading side
// by side (--jobs, shards on a shared folder) never read half an entry; an entry that does not read
// back whole (truncated, another version's layout) is a miss, never an error.
//
// Keys that are never asked for again (a new build of shadelab, an edited rubric) would make the
// folder grow without end: after each store the least recently used entries are removed until the
// folder holds at most its budget (4 GiB, or $SHADELAB_CACHE_MB MiB). A load marks its entry used.
#pragma once
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/measure/image.h"

namespace shadelab {

// A 128-bit content hash (two independent FNV-1a lanes): a cache key, not a defence against
// someone forging collisions; nothing a student hands in goes into a key.
class ContentHash {
 public:
  ContentHash& add(std::string_view bytes);
  // The file's bytes, preceded by its length so that two files cannot run into each other; a file
  // that cannot be read adds a marker instead.
  ContentHash& addFile(const std::filesystem::path& file);
  // Every regular file under `dir`, in order of their relative paths, each name with its bytes.
  ContentHash& addTree(const std::filesystem::path& dir);
  std::string hex() const;  // 32 hex digits

 private:
  uint64_t a_ = 0xcbf29ce484222325ull, b_ = 0x84222325cbf29ce4ull;
};

struct CachedSolution {
  ImageF frame;                  // the solution's frame
  std::vector<ImageF> truths;    // the lab's references for the configuration (empty when no check needs them)
  std::vector<ImageF> mistakes;  // each of the rubric's mistakes drawn in the configuration, in its order
  // The solution's slips (grade/mutants.h) that build and draw differently here, at half size
  // (downsample, app/measure/image.h); absent until drawSlips has run.
  std::vector<ImageF> slips;
  // What the solution's phase reports: renderer, vs_truth, "mistakes": [{name, distance}], each
  // mistake's frame against the solution's (frameDistance), and once drawn "slips": [{index, kind,
  // cause, cause_and_fix, separation}], one for each of `slips`.
  nlohmann::json numbers;
};

// Frames kept under a key of their own, beside a solution's entry, and read only by the runs that
// need them (the solution drawn at other settings, grade/configuration_frames.h: SettingFrames).
struct CachedFrames {
  nlohmann::json numbers;
  std::vector<ImageF> frames;
};

class SolutionCache {
 public:
  SolutionCache() = default;  // off: every lookup misses, nothing is stored
  explicit SolutionCache(std::filesystem::path dir,
                         uint64_t budgetBytes = defaultBudgetBytes());  // created on the first store
  // $SHADELAB_CACHE_MB (MiB, a whole number >= 1), else 4 GiB.
  static uint64_t defaultBudgetBytes();
  bool enabled() const { return !dir_.empty(); }
  const std::filesystem::path& dir() const { return dir_; }

  bool load(const std::string& key, CachedSolution& out) const;
  // "" on success, else why it could not be stored (grading goes on without it). An entry over
  // 128 MiB is not kept (it would pass a grading child's file-size limit).
  std::string store(const std::string& key, const CachedSolution& entry) const;
  bool load(const std::string& key, CachedFrames& out) const;
  std::string store(const std::string& key, const CachedFrames& entry) const;

 private:
  std::filesystem::path file(const std::string& key) const;
  void markUsed(const std::string& key) const;  // the last to be pruned
  // Written under a temporary name and renamed into place, then the folder pruned.
  std::string write(const std::string& key, const std::string& bytes) const;
  // Removes the least recently used entries (by modification time) until the folder's entries
  // hold at most budget_ bytes, never `keep`.
  void prune(const std::filesystem::path& keep) const;
  std::filesystem::path dir_;
  uint64_t budget_ = 0;
};

// $SHADELAB_CACHE, else $XDG_CACHE_HOME/shadelab, else ~/.cache/shadelab; "solutions" under it.
std::filesystem::path defaultSolutionCacheDir();

}  // namespace shadelab

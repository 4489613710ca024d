// What a student has done, kept with their files: each exercise's last Check (score, pass or
// not, when), in `shadelab-progress.json` at the top of their shader folder. The window reads it on start
// and lists it beside each exercise; the page keeps it in its persistent storage with the files.
// A file that does not read is taken for no progress, never an error: it is the student's folder.
#pragma once
#include <filesystem>
#include <map>
#include <string>

namespace shadelab {

struct ExerciseProgress {
  double percent = 0.0;
  bool passed = false;
  std::string when;  // "2026-11-28 17:20", local time
};

using Progress = std::map<std::string, ExerciseProgress>;  // exercise id -> its last Check

std::filesystem::path progressFile(const std::filesystem::path& studentFolder);
Progress readProgress(const std::filesystem::path& studentFolder);
// Records `id`'s Check and writes the file (written aside and renamed). Returns "" or why not.
std::string recordProgress(const std::filesystem::path& studentFolder, Progress& progress, const std::string& id,
                           double percent, bool passed);

}  // namespace shadelab

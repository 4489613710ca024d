#include "app/grade/progress.h"

#include <nlohmann/json.hpp>

#include "app/measure/report.h"
#include "app/util/format.h"
#include "app/util/read_file.h"

namespace shadelab {

namespace fs = std::filesystem;

fs::path progressFile(const fs::path& studentFolder) { return studentFolder / "shadelab-progress.json"; }

Progress readProgress(const fs::path& studentFolder) {
  Progress progress;
  std::error_code ec;
  const fs::path file = progressFile(studentFolder);
  if (!fs::is_regular_file(file, ec) || fs::file_size(file, ec) > (1u << 20)) return progress;
  const nlohmann::json j = nlohmann::json::parse(readWholeFile(file), nullptr, false);
  if (!j.is_object() || !j.contains("exercises") || !j["exercises"].is_object()) return progress;
  for (auto& [id, e] : j["exercises"].items()) {
    if (!e.is_object() || !e.contains("percent") || !e["percent"].is_number()) continue;
    ExerciseProgress p;
    p.percent = e["percent"].get<double>();
    p.passed = e.contains("passed") && e["passed"].is_boolean() && e["passed"].get<bool>();
    if (e.contains("when") && e["when"].is_string()) p.when = e["when"].get<std::string>();
    progress[id] = p;
  }
  return progress;
}

std::string recordProgress(const fs::path& studentFolder, Progress& progress, const std::string& id, double percent,
                           bool passed) {
  progress[id] = {percent, passed, localTimeNow("%Y-%m-%d %H:%M")};
  nlohmann::json exercises = nlohmann::json::object();
  for (auto& [key, p] : progress) exercises[key] = {{"percent", p.percent}, {"passed", p.passed}, {"when", p.when}};
  const nlohmann::json j = {{"what", "ShadeLab: each exercise's last Check in the window or the page"},
                            {"exercises", exercises}};
  return writeTextFile(progressFile(studentFolder).string(), j.dump(2) + "\n");
}

}  // namespace shadelab

#include "app/ui/exercise_panel.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <tuple>

#include "app/host/lab_host.h"
#include "app/ui/platform.h"
#include "app/ui/shader_editor.h"
#include "app/util/read_file.h"

namespace shadelab {

namespace fs = std::filesystem;

namespace {

// The folders a Check reads the student's files from: the host's own, ahead of the built-in one.
std::vector<fs::path> studentFolders(LabHost& host) {
  std::vector<fs::path> dirs;
  for (auto& root : host.shaders().searchPath().roots())
    if (root != builtinShaderDir()) dirs.push_back(root);
  return dirs;
}

// The starter's files into the student's folder, never over a file already there (their work);
// the lab switched to the exercise's and its first file opened in the editor.
StatusLine openStarter(const std::string& id, LabHost& host, ShaderEditor& editor) {
  Exercise ex;
  if (auto e = loadExercise(id, ex); !e.empty()) return StatusLine::failed(e);
  if (host.lab().id() != ex.lab)
    if (auto e = host.selectLab(ex.lab); !e.empty()) return StatusLine::failed(e);
  std::vector<std::string> copied, kept;
  if (auto e = copyStarter(ex, editor.folder, copied, kept); !e.empty()) return StatusLine::failed(e);
  persistStudentFiles();
  host.pollChanges();  // the new files shadow the lab's own from this frame on
  editor.open(host, ex.files.front());
  const auto join = [](const std::vector<std::string>& names) {
    std::string out;
    for (auto& n : names) out += (out.empty() ? "" : ", ") + n;
    return out;
  };
  std::string status = "opened " + ex.files.front();
  if (!copied.empty()) status += "; the starter's " + join(copied) + " copied into " + editor.folder.string();
  if (!kept.empty()) status += "; your " + join(kept) + " kept as it is";
  return StatusLine::done(status);
}

const ImVec4 kPass{0.45f, 0.85f, 0.45f, 1.0f}, kPartial{0.95f, 0.8f, 0.3f, 1.0f}, kFail{1.0f, 0.45f, 0.4f, 1.0f};

}  // namespace

void ExercisePanel::select(const std::string& id) {
  selected = id;
  statement = readWholeFile(exerciseRootOf(id) / id / "statement.md");
}

StatusLine openCourseFolder(ExercisePanel& panel, const fs::path& folder) {
  const std::vector<std::string> ids = listExercises(folder);
  if (ids.empty())
    return StatusLine::failed(folder.string() +
                              " holds no exercise (a course folder holds LAB/NAME/rubric.json, as exercises/ does)");
  std::string problems;
  for (const std::string& id : ids)
    if (Exercise ex; !loadExercise(folder, id, ex).empty()) problems += (problems.empty() ? "" : ", ") + id;
  addCourseFolder(folder);
  panel.listed = false;  // listed again on the next frame, this course first
  panel.select(ids.front());
  std::string list;
  for (const std::string& id : ids) list += (list.empty() ? "" : ", ") + id;
  const std::string opened = "course " + folder.filename().string() + " opened (Exercises): " + list;
  if (problems.empty()) return StatusLine::done(opened);
  return StatusLine::failed(opened + "; these do not load, `shadelab exercise check` says why: " + problems);
}

void drawExercisePanel(ExercisePanel& panel, LabHost& host, ShaderEditor& editor, StatusLine& status) {
  if (!panel.listed) {  // once: the exercises ship with the program
    // A course's exercises first, under its folder's name; then as exercises/README.md lists
    // them: per lab, the guided exercises before those written from scratch.
    struct Entry {
      std::string course, lab, level, id;
    };
    std::vector<Entry> entries;
    const std::filesystem::path builtin = builtinExercisesRoot();
    for (auto& id : listExercises()) {
      Exercise ex;
      const bool loaded = loadExercise(id, ex).empty();
      const std::filesystem::path root = exerciseRootOf(id);
      const std::string course = root == builtin ? "" : root.filename().string();
      entries.push_back({course, id.substr(0, id.find('/')), loaded ? ex.level : "", id});
    }
    const auto rank = [](const Entry& e) { return e.level == "guided" ? 0 : e.level == "from-scratch" ? 1 : 2; };
    std::stable_sort(entries.begin(), entries.end(), [&](const Entry& a, const Entry& b) {
      return std::tuple(a.course.empty(), a.course, a.lab, rank(a), a.id) <
             std::tuple(b.course.empty(), b.course, b.lab, rank(b), b.id);
    });
    for (size_t i = 0; i < entries.size(); ++i) {
      const Entry& e = entries[i];
      const bool first =
          i == 0 || e.course != entries[i - 1].course || e.lab != entries[i - 1].lab || e.level != entries[i - 1].level;
      const std::string title =
          (e.course.empty() ? "" : e.course + " / ") + e.lab + (e.level.empty() ? "" : ": " + e.level);
      panel.headers.push_back(first ? title : "");
      panel.ids.push_back(e.id);
    }
    panel.listed = true;
  }
  if (panel.ids.empty()) {
    ImGui::TextDisabled("No exercises in %s.", builtinExercisesRoot().c_str());
    return;
  }
  if (panel.reveal) {  // a Check runs: its results in view, below the section's top
    ImGui::SetScrollHereY(0.0f);
    panel.reveal = panel.check.running() || panel.checkRequested;
  }
  const std::string lab(host.lab().id());
  ImGui::SetNextItemWidth(-1);
  if (ImGui::BeginCombo("##exercise", panel.selected.empty() ? "Pick an exercise" : panel.selected.c_str())) {
    for (size_t i = 0; i < panel.ids.size(); ++i) {
      const std::string& id = panel.ids[i];
      const bool thisLab = id.rfind(lab + "/", 0) == 0;  // the lab on screen first to the eye
      if (!panel.headers[i].empty()) {
        if (i > 0) ImGui::Separator();
        ImGui::TextDisabled("%s", panel.headers[i].c_str());
      }
      if (!thisLab) ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
      if (ImGui::Selectable(("  " + id).c_str(), id == panel.selected)) panel.select(id);
      if (!thisLab) ImGui::PopStyleColor();
    }
    ImGui::EndCombo();
  }
  if (panel.selected.empty()) {
    ImGui::TextWrapped(
        "Each exercise asks for one function of a lab's shader: open its starter, write the "
        "function in the editor, and press Check to have it graded here.");
    ImGui::TextDisabled("A course of your own: drop its folder on the window (in the page: its .zip).");
    return;
  }
  if (editor.folder.empty()) {
    ImGui::TextDisabled("Start with --shaders DIR to work on an exercise here.");
  } else if (ImGui::Button("Open the starter")) {
    status = openStarter(panel.selected, host, editor);
  }
  ImGui::SameLine();
  ImGui::Checkbox("Statement", &panel.showStatement);
  ImGui::SameLine();
  ImGui::BeginDisabled(panel.check.running());
  if (ImGui::Button("Check")) panel.checkRequested = true;
  ImGui::EndDisabled();
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip(
        "Grades your files as `shadelab grade --exercise %s` does: the rubric's frames against the "
        "solution's and the truth, here in the window.",
        panel.selected.c_str());
  if (panel.showStatement) {
    ImGui::BeginChild("statement", {0, 220 * ImGui::GetIO().FontGlobalScale}, true);
    ImGui::PushTextWrapPos(0);
    ImGui::TextUnformatted(panel.statement.c_str());
    ImGui::PopTextWrapPos();
    ImGui::EndChild();
  }

  const ExerciseCheck& check = panel.check;
  if (check.id() != panel.selected) return;
  if (check.running()) {
    const float done = float(check.configurationsDone()) / float(std::max<size_t>(check.configurations(), 1));
    char label[64];
    std::snprintf(label, sizeof label, "configuration %zu of %zu", check.configurationsDone() + 1,
                  check.configurations());
    ImGui::ProgressBar(done, {-1, 0}, label);
  }
  if (!check.error().empty()) {
    ImGui::PushTextWrapPos(0);
    ImGui::TextColored({1.0f, 0.45f, 0.4f, 1.0f}, "Could not check: %s", check.error().c_str());
    ImGui::PopTextWrapPos();
  }
  // The grader's results, laid out for a narrow panel: the total first, then per check its grade,
  // name and points, the number against its bound, and the hint when it lost points.
  const ExerciseResult& r = check.result();
  ImGui::PushTextWrapPos(0);
  if (check.finished())
    ImGui::TextColored(r.passed() ? kPass : kFail, "%.4g / %.4g points (%.1f%%), pass mark %.0f%%: %s", r.earned,
                       r.total, r.percent(), r.passMark, r.passed() ? "passed" : "not passed");
  if (check.finished() && !r.diagnosis.empty()) ImGui::TextColored(kFail, "diagnosis: %s", r.diagnosis.c_str());
  for (auto& f : r.missingFiles) ImGui::TextColored(kFail, "%s is not in your folder: open the starter.", f.c_str());
  std::vector<std::string> said;  // each build error once: every configuration compiles the same file
  for (auto& c : r.configurations) {
    for (auto& e : c.errors)
      if (std::find(said.begin(), said.end(), errorWithoutProgram(e)) == said.end()) {
        said.push_back(errorWithoutProgram(e));
        ImGui::TextColored(kFail, "%s", e.c_str());
      }
    for (auto& k : c.checks) {
      const ImVec4 colour = k.grade == Grade::Full ? kPass : k.grade == Grade::Partial ? kPartial : kFail;
      ImGui::TextColored(colour, "%-7s %s: %s  %.3g/%.3g", gradeName(k.grade), c.name.c_str(), k.check.name.c_str(),
                         k.earned, k.check.points);
      ImGui::Indent();
      if (std::isfinite(k.value))
        ImGui::TextDisabled("%s %.4g, full marks at <= %.4g", k.check.metric.c_str(), k.value, k.fullBound);
      if (!k.message.empty() && c.errors.empty()) ImGui::TextUnformatted(k.message.c_str());
      ImGui::Unindent();
    }
  }
  for (auto& n : r.notes) ImGui::TextDisabled("note: %s", n.c_str());
  ImGui::PopTextWrapPos();
}

bool stepExerciseCheck(ExercisePanel& panel, LabHost& host, StatusLine& status) {
  if (panel.checkRequested) {
    panel.checkRequested = false;
    if (panel.selected.empty()) {
      status = StatusLine::failed("Check: pick an exercise first");
    } else if (auto e = panel.check.start(panel.selected, studentFolders(host)); !e.empty()) {
      status = StatusLine::failed("Check: " + e);
    } else {
      std::printf("checking %s\n", panel.selected.c_str());
      panel.reveal = true;
    }
    return panel.check.running();
  }
  if (!panel.check.running()) return false;
  panel.check.step();
  if (!panel.check.running()) {  // finished: the grader's lines on the terminal (the page's console) too
    for (auto& line : panel.check.lines()) std::printf("%s\n", line.c_str());
    if (!panel.check.error().empty()) std::printf("check: %s\n", panel.check.error().c_str());
    std::fflush(stdout);
  }
  return panel.check.running();
}

}  // namespace shadelab

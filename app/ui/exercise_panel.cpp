#include "app/ui/exercise_panel.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <tuple>

#include "app/grade/pixel_trace.h"
#include "app/host/configure.h"
#include "app/host/lab_host.h"
#include "app/host/share_link.h"
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

// The student's files set back to the starter's, theirs kept beside them as dated copies.
StatusLine resetStarter(const std::string& id, LabHost& host, ShaderEditor& editor) {
  Exercise ex;
  if (auto e = loadExercise(id, ex); !e.empty()) return StatusLine::failed(e);
  std::vector<std::string> kept;
  if (auto e = resetToStarter(ex, editor.folder, kept); !e.empty()) return StatusLine::failed(e);
  persistStudentFiles();
  host.pollChanges();
  editor.open(host, ex.files.front());
  std::string text = "reset " + id + " to the starter";
  for (size_t i = 0; i < kept.size(); ++i) text += (i ? ", " : "; yours kept as ") + kept[i];
  return StatusLine::done(text);
}

const ImVec4 kPass{0.45f, 0.85f, 0.45f, 1.0f}, kPartial{0.95f, 0.8f, 0.3f, 1.0f}, kFail{1.0f, 0.45f, 0.4f, 1.0f};

gl::Texture2D textureOf(const ImageF& image) {
  if (image.rgba.empty()) return {};
  const int w = image.size.x, h = image.size.y;
  std::vector<uint8_t> bytes(size_t(w) * size_t(h) * 4);
  for (int y = 0; y < h; ++y)  // rows bottom-up, as GL numbers them; opaque, as the viewport draws them
    for (size_t i = 0; i < size_t(w) * 4; ++i) {
      const float v = i % 4 == 3 ? 1.0f : image.rgba[size_t(h - 1 - y) * size_t(w) * 4 + i];
      bytes[size_t(y) * size_t(w) * 4 + i] =
          uint8_t(std::lround(std::isfinite(v) ? std::clamp(v, 0.0f, 1.0f) * 255.0f : 255.0f));
    }
  gl::SamplerState sampler;
  sampler.minFilter = GL_LINEAR;
  sampler.wrapS = sampler.wrapT = GL_CLAMP_TO_EDGE;
  return gl::Texture2D::fromRgba8(image.size, bytes.data(), sampler, false);
}

ImTextureID imguiTexture(const gl::Texture2D& t) { return reinterpret_cast<ImTextureID>(intptr_t(t.id())); }

// An inspection's table into the section, and onto the terminal (the page's console) as Check's
// lines go; the point stays marked while the camera is the one it was pressed with.
void showInspection(ExercisePanel& panel, LabHost& host, std::vector<InspectionRow> rows) {
  panel.inspection = std::move(rows);
  panel.inspectedView = host.camera().view();
  panel.picture = {};
  panel.pictureSays.clear();
  for (auto& row : panel.inspection) std::printf("%s\n", row.text.c_str());
  std::fflush(stdout);
}

// With no exercise open, the lab's own pass at the pixel, drawn as the view is (its settings and
// camera as a shared link carries them, at the view's size): its values alone.
StatusLine inspectViewPixel(ExercisePanel& panel, LabHost& host) {
  const OpenedLink view = openLink(shareLink(host).fragment);
  LabInspection in;
  if (auto e = inspectLabPixel(
          {view.lab, view.scene, view.camera, view.sets, {}, {}, panel.inspectViewport, panel.inspectPixel},
          studentFolders(host), in);
      !e.empty())
    return StatusLine::failed("Inspect: " + e);
  panel.inspected = {};
  showInspection(panel, host, labInspectionRows(in));
  return StatusLine::done("inspected pixel " + std::to_string(panel.inspectPixel.x) + ", " +
                          std::to_string(panel.inspectPixel.y) + " of the view");
}

// The inspector at the requested pixel of the configuration on screen. The grader's frame is drawn
// at the rubric's size: the same point of the view lies in the same direction from the camera,
// its offset from the centre scaled by the two projections' vertical extents (a portrait view
// widens its vertical field to keep the horizontal one: OrbitCamera::projection).
StatusLine inspectShownPixel(ExercisePanel& panel, LabHost& host) {
  if (panel.selected.empty()) return inspectViewPixel(panel, host);
  if (panel.shown < 0 || panel.shown >= int(panel.configurations.size()))
    return StatusLine::failed("Inspect: show one of the exercise's configurations first");
  Exercise ex;
  if (auto e = loadExercise(panel.selected, ex); !e.empty()) return StatusLine::failed("Inspect: " + e);
  size_t index = 0;
  while (index < ex.configurations.size() && ex.configurations[index].name != panel.configurations[size_t(panel.shown)])
    ++index;
  const glm::vec2 view(panel.inspectViewport), frame(ex.size);
  const auto halfTan = [&](glm::vec2 size) { return 1.0f / host.camera().projection(size.x / size.y)[1][1]; };
  const float scale = (halfTan(view) / view.y) / (halfTan(frame) / frame.y);  // frame pixels per view pixel
  const glm::vec2 at = frame * 0.5f + (glm::vec2(panel.inspectPixel) + 0.5f - view * 0.5f) * scale;
  const glm::ivec2 pixel(glm::floor(at));
  if (pixel.x < 0 || pixel.y < 0 || pixel.x >= ex.size.x || pixel.y >= ex.size.y)
    return StatusLine::failed("Inspect: that point of the view is outside the grader's frame (" +
                              std::to_string(ex.size.x) + "x" + std::to_string(ex.size.y) + ")");
  PixelInspection in;
  if (auto e = inspectPixel(ex, index, studentFolders(host), pixel, in); !e.empty())
    return StatusLine::failed("Inspect: " + e);
  panel.inspected = std::move(in);
  panel.inspectedConfiguration = index;
  showInspection(panel, host, inspectionRows(panel.inspected));
  return StatusLine::done("inspected pixel " + std::to_string(pixel.x) + ", " + std::to_string(pixel.y) +
                          " of the grader's frame");
}

// The clicked variable over the whole frame of the inspected configuration.
StatusLine drawClickedVariable(ExercisePanel& panel, LabHost& host) {
  Exercise ex;
  if (auto e = loadExercise(panel.inspected.exercise, ex); !e.empty()) return StatusLine::failed("Inspect: " + e);
  VariablePicture picture;
  if (auto e = drawVariable(ex, panel.inspectedConfiguration, studentFolders(host), panel.pictureName,
                            panel.pictureLine, picture);
      !e.empty())
    return StatusLine::failed("Inspect: " + e);
  panel.picture = textureOf(variableImage(picture));
  panel.pictureSays = describeVariableImage(picture);
  return StatusLine::done("drew `" + panel.pictureName + "` over the frame");
}

// The last Check's pictures as textures, made once per Check.
void makePictures(ExercisePanel& panel) {
  const ExerciseCheck& check = panel.check;
  if (panel.picturesOf != check.generation()) {  // a new Check: its pictures come one configuration a step
    panel.pictures.clear();
    panel.wipes.clear();
    panel.picturesOf = check.generation();
  }
  for (size_t i = panel.pictures.size(); i < check.pictures().size(); ++i) {  // only the ones new since the last frame
    const auto& p = check.pictures()[i];
    panel.pictures.push_back({textureOf(p.student), textureOf(p.solution), textureOf(p.difference)});
    panel.wipes.push_back(-1.0f);  // < 0: the wipe folded away
  }
}

// Configuration `i` lost points: the student's frame, the solution's and their difference side by
// side (a click puts the configuration in the viewport), and on demand one picture that wipes from
// the student's frame (left of the line) to the solution's (right of it) as its slider moves.
void drawPictures(ExercisePanel& panel, LabHost& host, StatusLine& status, size_t i) {
  if (i >= panel.pictures.size()) return;
  auto& [student, solution, difference] = panel.pictures[i];
  if (!student || !solution) return;
  ImGui::PushID(int(i));
  const float width = (ImGui::GetContentRegionAvail().x - 2.0f * ImGui::GetStyle().ItemSpacing.x) / 3.0f;
  const float aspect = float(student.size().y) / float(std::max(student.size().x, 1));
  const char* captions[] = {"yours", "solution", "difference x4"};
  const gl::Texture2D* textures[] = {&student, &solution, &difference};
  for (int k = 0; k < 3; ++k) {
    if (k > 0) ImGui::SameLine();
    ImGui::BeginGroup();
    ImGui::PushID(k);
    if (ImGui::ImageButton(imguiTexture(*textures[k]), {width, width * aspect}, {0, 1}, {1, 0}, 0))
      status = showConfiguration(panel, host, int(i));
    ImGui::PopID();
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Put this configuration in the viewport");
    ImGui::TextDisabled("%s", captions[k]);
    ImGui::EndGroup();
  }
  float& wipe = panel.wipes[i];
  bool comparing = wipe >= 0.0f;
  if (ImGui::Checkbox("Compare yours and the solution's", &comparing)) wipe = comparing ? 0.5f : -1.0f;
  if (comparing) {
    const float full = ImGui::GetContentRegionAvail().x, height = full * aspect, s = std::clamp(wipe, 0.0f, 1.0f);
    const ImVec2 o = ImGui::GetCursorScreenPos();
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->AddImage(imguiTexture(student), o, {o.x + full * s, o.y + height}, {0, 1}, {s, 0});
    draw->AddImage(imguiTexture(solution), {o.x + full * s, o.y}, {o.x + full, o.y + height}, {s, 1}, {1, 0});
    draw->AddLine({o.x + full * s, o.y}, {o.x + full * s, o.y + height}, IM_COL32(255, 220, 0, 255), 2.0f);
    ImGui::Dummy({full, height});
    ImGui::SetNextItemWidth(-1);
    ImGui::SliderFloat("##wipe", &wipe, 0.0f, 1.0f, "yours  <  >  solution");
  }
  ImGui::PopID();
}

}  // namespace

void ExercisePanel::select(const std::string& id) {
  selected = id;
  statement = readWholeFile(exerciseRootOf(id) / id / "statement.md");
  configurations.clear();
  files.clear();
  shown = -1;
  Exercise ex;
  if (loadExercise(id, ex).empty()) {
    files = ex.files;
    for (auto& c : ex.configurations)
      if (!c.hidden() && c.function < 0) configurations.push_back(c.name);  // a frame to show, not a probe's table
  }
  showExerciseText(id, statement, "");
}

StatusLine openExercise(ExercisePanel& panel, LabHost& host, const std::string& id) {
  panel.select(id);
  if (panel.configurations.empty()) {
    Exercise ex;
    if (auto e = loadExercise(id, ex); !e.empty()) return StatusLine::failed(e);
    if (host.lab().id() != ex.lab)
      if (auto e = host.selectLab(ex.lab); !e.empty()) return StatusLine::failed(e);
    return StatusLine::done("opened " + id);
  }
  return showConfiguration(panel, host, 0);
}

StatusLine showConfiguration(ExercisePanel& panel, LabHost& host, int index) {
  Exercise ex;
  if (auto e = loadExercise(panel.selected, ex); !e.empty()) return StatusLine::failed(e);
  dropHiddenConfigurations(ex.configurations);
  if (index < 0 || index >= int(ex.configurations.size())) return StatusLine::failed("no such configuration");
  const Configuration& c = ex.configurations[size_t(index)];
  if (host.lab().id() != ex.lab)
    if (auto e = host.selectLab(ex.lab); !e.empty()) return StatusLine::failed(e);
  const std::string scene = c.scene.empty() ? std::string(host.lab().defaultScene()) : c.scene;
  if (host.sceneId() != scene)
    if (auto e = host.selectScene(scene); !e.empty()) return StatusLine::failed(e);
  host.resetParams();
  host.resetCamera();
  std::vector<std::string> sets;
  for (auto& [key, value] : c.settings) sets.push_back(key + "=" + value);
  if (auto e = configureHost(host, {}, {}, sets, {}, c.camera); !e.empty()) return StatusLine::failed(e);
  panel.shown = index;
  return StatusLine::done(panel.selected + ": '" + c.name + "' in the viewport, drawn with your files");
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

void drawInspection(ExercisePanel& panel) {
  // The line where the values part stands out; a click on a value's line draws it over the frame.
  ImGui::PushTextWrapPos(0);
  const std::vector<TracePoint>& points = panel.inspected.student.values.points;
  for (size_t r = 0; r < panel.inspection.size(); ++r) {
    const InspectionRow& row = panel.inspection[r];
    // An exercise's values only (the lab's own pass has no solution to draw beside).
    const bool clickable =
        row.point >= 0 && size_t(row.point) < points.size() && points[size_t(row.point)].kind != TracePoint::Kind::Sub;
    if (row.departs) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.6f, 0.3f, 1.0f));
    if (clickable) {
      // A selectable the size of the wrapped text, the text drawn over it.
      ImGui::PushID(int(r));
      const ImVec2 at = ImGui::GetCursorPos();
      const ImVec2 size = ImGui::CalcTextSize(row.text.c_str(), nullptr, false, ImGui::GetContentRegionAvail().x);
      if (ImGui::Selectable("##row", false, ImGuiSelectableFlags_AllowItemOverlap, size)) {
        const TracePoint& p = points[size_t(row.point)];
        panel.pictureRequested = true;
        panel.pictureName = p.kind == TracePoint::Kind::Returned ? "return" : p.name;
        panel.pictureLine = p.kind == TracePoint::Kind::Returned ? 0 : p.line;
      }
      if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Draw this value over the whole frame, yours beside the solution's");
      ImGui::SetCursorPos(at);
      ImGui::TextUnformatted(row.text.c_str());
      ImGui::PopID();
    } else {
      ImGui::TextUnformatted(row.text.c_str());
    }
    if (row.departs) ImGui::PopStyleColor();
  }
  if (panel.picture) {
    const float width = ImGui::GetContentRegionAvail().x;
    const float aspect = float(panel.picture.size().y) / float(std::max(panel.picture.size().x, 1));
    ImGui::Image(imguiTexture(panel.picture), {width, width * aspect}, {0, 1}, {1, 0});
    ImGui::TextDisabled("%s", panel.pictureSays.c_str());
  }
  ImGui::PopTextWrapPos();
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
  editor.exerciseFiles = panel.files;
  if (panel.progressFolder != editor.folder) {
    panel.progressFolder = editor.folder;
    panel.progress = editor.folder.empty() ? Progress{} : readProgress(editor.folder);
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
      std::string label = "  " + id;
      if (auto p = panel.progress.find(id); p != panel.progress.end())
        label +=
            "   " + std::to_string(int(std::lround(p->second.percent))) + "%" + (p->second.passed ? ", passed" : "");
      if (ImGui::Selectable(label.c_str(), id == panel.selected)) status = openExercise(panel, host, id);
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
  // The buttons in the order a student needs them, the ones used most first (a narrow panel cuts
  // the row's end): the starter, Check, the statement, and starting again.
  if (editor.folder.empty()) {
    ImGui::TextDisabled("Start with --shaders DIR to work on an exercise here.");
  } else {
    if (ImGui::Button("Open the starter")) status = openStarter(panel.selected, host, editor);
    ImGui::SameLine();
  }
  ImGui::BeginDisabled(panel.check.running());
  if (ImGui::Button("Check")) panel.checkRequested = true;
  ImGui::EndDisabled();
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip(
        "Grades your files as `shadelab grade --exercise %s` does: the rubric's frames against the "
        "solution's and the truth, here in the window.",
        panel.selected.c_str());
  ImGui::SameLine();
  ImGui::Checkbox("Statement", &panel.showStatement);
  if (!editor.folder.empty()) {
    ImGui::SameLine();
    if (ImGui::Button("Reset")) ImGui::OpenPopup("reset");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Start again from the starter; your file is kept as a dated copy");
    if (ImGui::BeginPopup("reset")) {
      ImGui::TextUnformatted("Set your files back to the starter?\nEach is kept beside it as a dated copy.");
      if (ImGui::Button("Reset to the starter")) {
        status = resetStarter(panel.selected, host, editor);
        ImGui::CloseCurrentPopup();
      }
      ImGui::SameLine();
      if (ImGui::Button("Cancel")) ImGui::CloseCurrentPopup();
      ImGui::EndPopup();
    }
  }
  if (auto p = panel.progress.find(panel.selected); p != panel.progress.end())
    ImGui::TextDisabled("Last Check %s: %.1f%%, %s", p->second.when.c_str(), p->second.percent,
                        p->second.passed ? "passed" : "not passed");
  if (!panel.configurations.empty()) {  // the rubric's configurations, each drawn live with the student's files
    ImGui::SetNextItemWidth(-1);
    const std::string label = panel.shown >= 0 && panel.shown < int(panel.configurations.size())
                                  ? "Configuration: " + panel.configurations[size_t(panel.shown)]
                                  : std::string("Show a configuration...");
    if (ImGui::BeginCombo("##configuration", label.c_str())) {
      for (size_t i = 0; i < panel.configurations.size(); ++i)
        if (ImGui::Selectable(panel.configurations[i].c_str(), int(i) == panel.shown))
          status = showConfiguration(panel, host, int(i));
      ImGui::EndCombo();
    }
  }
  if (panel.showStatement) {
    ImGui::BeginChild("statement", {0, 220 * ImGui::GetIO().FontGlobalScale}, true);
    ImGui::PushTextWrapPos(0);
    ImGui::TextUnformatted(panel.statement.c_str());
    ImGui::PopTextWrapPos();
    ImGui::EndChild();
  }

  if (!panel.inspection.empty() &&
      ImGui::CollapsingHeader("At the pixel (I over the view)", ImGuiTreeNodeFlags_DefaultOpen))
    drawInspection(panel);

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
  makePictures(panel);
  std::vector<std::string> said;  // each build error once: every configuration compiles the same file
  for (size_t i = 0; i < r.configurations.size(); ++i) {
    const ConfigurationResult& c = r.configurations[i];
    ImGui::Separator();
    ImGui::TextUnformatted(c.name.c_str());
    drawPictures(panel, host, status, i);
    for (auto& e : c.errors)
      if (std::find(said.begin(), said.end(), errorWithoutProgram(e)) == said.end()) {
        said.push_back(errorWithoutProgram(e));
        ImGui::TextColored(kFail, "%s", e.c_str());
      }
    for (auto& k : c.checks) {
      const ImVec4 colour = k.grade == Grade::Full ? kPass : k.grade == Grade::Partial ? kPartial : kFail;
      if (k.check.isCondition())
        ImGui::TextColored(colour, "%-7s %s  (a condition)", gradeName(k.grade), k.check.name.c_str());
      else
        ImGui::TextColored(colour, "%-7s %s  %.3g/%.3g", gradeName(k.grade), k.check.name.c_str(), k.earned,
                           k.check.points);
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

void requestInspection(ExercisePanel& panel, glm::ivec2 pixel, glm::ivec2 viewport) {
  panel.inspectRequested = true;
  panel.inspectPixel = pixel;
  panel.inspectViewport = glm::max(viewport, glm::ivec2(1));
}

bool stepExerciseCheck(ExercisePanel& panel, LabHost& host, StatusLine& status) {
  if (panel.inspectRequested) {
    panel.inspectRequested = false;
    status = inspectShownPixel(panel, host);
  }
  if (panel.pictureRequested) {
    panel.pictureRequested = false;
    status = drawClickedVariable(panel, host);
  }
  if (panel.checkRequested) {
    panel.checkRequested = false;
    if (panel.selected.empty()) {
      status = StatusLine::failed("Check: pick an exercise first");
    } else if (auto e = panel.check.start(panel.selected, studentFolders(host)); !e.empty()) {
      status = StatusLine::failed("Check: " + e);
    } else {
      std::printf("checking %s\n", panel.selected.c_str());
      showExerciseText(panel.selected, panel.statement, "Checking...");
      panel.reveal = true;
    }
    return panel.check.running();
  }
  if (!panel.check.running()) return false;
  panel.check.step();
  if (!panel.check.running() && panel.check.finished() && !panel.progressFolder.empty()) {  // kept for next time
    const ExerciseResult& r = panel.check.result();
    if (auto e = recordProgress(panel.progressFolder, panel.progress, r.id, r.percent(), r.passed()); !e.empty())
      status = StatusLine::failed("progress: " + e);
    persistStudentFiles();
  }
  if (!panel.check.running()) {  // finished: the grader's lines on the terminal (the page's console) too
    std::string text;
    for (auto& line : panel.check.lines()) {
      std::printf("%s\n", line.c_str());
      text += line + "\n";
    }
    if (!panel.check.error().empty()) text += "Could not check: " + panel.check.error() + "\n";
    showExerciseText(panel.selected, panel.statement, text);
    const auto& pictures = panel.check.pictures();
    for (size_t i = 0; i < pictures.size(); ++i)  // what the section shows beside the lines
      if (!pictures[i].student.rgba.empty())
        std::printf("pictures of '%s': yours, the solution's, the difference (%dx%d)\n",
                    panel.check.result().configurations[i].name.c_str(), pictures[i].student.size.x,
                    pictures[i].student.size.y);
    if (!panel.check.error().empty()) std::printf("check: %s\n", panel.check.error().c_str());
    std::fflush(stdout);
  }
  return panel.check.running();
}

}  // namespace shadelab

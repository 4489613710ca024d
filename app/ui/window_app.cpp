// The main loop, top to bottom:
//   1. events (mouse on the viewport moves the camera; F12 takes a screenshot; dropped files)
//   2. render the lab into its offscreen target at the viewport's size
//   3. lay out the UI: lab/scene pickers and parameters (left), viewport with the running jobs
//      (centre), cost, measurements, the lab's panels, warnings and shaders (right)
//   4. draw the UI into the window and swap
#include "app/ui/window_app.h"

#include <memory>
#include <optional>

#include "app/host/share_link.h"
#include "app/host/soak.h"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include "app/gl/load_gl.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <utility>

#include "app/cli/session.h"
#include "app/gl/pixel_probe.h"
#include "app/grade/rubric.h"
#include "app/scene/scene_catalog.h"
#include "app/ui/exercise_panel.h"
#include "app/ui/frame_records.h"
#include "app/ui/panels.h"
#include "app/ui/platform.h"
#include "app/ui/shader_editor.h"
#include "app/ui/window_events.h"
#include "app/ui/window_files.h"
#include "app/ui/window_modes.h"

namespace shadelab {
namespace {

void onDrop(GLFWwindow* w, int count, const char** paths) {
  countWindowEvent(w);
  auto* app = static_cast<AppState*>(glfwGetWindowUserPointer(w));
  for (int i = 0; i < count; ++i) app->dropped.emplace_back(paths[i]);
}

// F12 (screenshot), F11 (presentation mode), Esc (leave it) and I (inspect) straight from GLFW: a press and
// release that land in one poll (a busy frame) would slip past ImGui's per-frame key state.
// Installed before ImGui's backend, which chains to it.
void onKey(GLFWwindow* w, int key, int, int action, int) {
  countWindowEvent(w);
  auto* app = static_cast<AppState*>(glfwGetWindowUserPointer(w));
  if (!app || action != GLFW_PRESS) return;
  if (key == GLFW_KEY_F12) app->screenshotRequested = true;
  if (key == GLFW_KEY_I) app->inspectKey = true;  // used (or dropped) by the viewport this frame
  if (key == GLFW_KEY_F11) app->presenting = !app->presenting;
  if (key == GLFW_KEY_ESCAPE) app->presenting = false;
}

// Text and every size in the style, uiScale times the defaults (from the defaults each time, so
// changing the scale back and forth does not compound).
void applyUiScale(AppState& app) {
  if (app.uiScale == app.appliedScale || ImGui::IsAnyItemActive()) return;  // not while its slider is dragged
  ImGuiStyle style;
  ImGui::StyleColorsDark(&style);
  style.ScaleAllSizes(app.uiScale);
  ImGui::GetStyle() = style;
  ImGui::GetIO().FontGlobalScale = app.uiScale;
  const float grow = app.uiScale / (app.appliedScale > 0 ? app.appliedScale : 1.0f);  // the panels grow with the text
  app.leftW *= grow, app.rightW *= grow;
  app.appliedScale = app.uiScale;
}

// Presentation mode's overlay: what the class needs to read from the back row (the lab, the
// frame's cost, the last error numbers), and the parameters folded away for the teacher.
void presentationOverlay(AppState& app, const std::vector<gl::PassTiming>& passes) {
  ImGui::SetNextWindowPos({12, 12});
  ImGui::SetNextWindowBgAlpha(0.72f);
  ImGui::Begin("Presenting", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings |
                   ImGuiWindowFlags_NoMove);
  ImGui::TextUnformatted(std::string(app.host->lab().title()).c_str());
  double gpu = 0;
  for (auto& p : passes) gpu += p.gpuMs;
  ImGui::Text("frame %.1f ms, GPU %.1f ms", app.history.frameMs.empty() ? 0.0f : app.history.frameMs.back(), gpu);
  if (const auto& measured = app.measurer->history(); !measured.empty()) {
    int shown = 0;
    for (auto& [key, value] : measured.back().values)
      if (shown++ < 3) ImGui::Text("%s %s", key.c_str(), formatNumber(value).c_str());
  }
  if (ImGui::CollapsingHeader("Parameters")) {
    ImGui::PushItemWidth(220 * app.uiScale);
    drawParamWidgets(app.host->lab());
    ImGui::PopItemWidth();
  }
  ImGui::TextDisabled("F11 or Esc: panels");
  ImGui::End();
}

void handleDrops(AppState& app) {
  for (const OpenedCourse& course : takeOpenedCourses()) {  // the page's dropped zips, unpacked
    if (course.problem.empty())
      app.dropped.push_back(course.folder);
    else
      app.message = StatusLine::failed(course.problem);
    std::fprintf(stderr, "shadelab: %s\n", app.message.text.c_str());
  }
  for (auto& path : app.dropped) {
    const std::filesystem::path p(path);
    const std::string ext = p.extension().string();
    std::error_code ec;
    if (std::filesystem::is_directory(p, ec)) {
      app.message = openCourseFolder(app.exercises, p);
      std::printf("shadelab: %s\n", app.message.text.c_str());  // the page's console, a terminal
      std::fflush(stdout);
    } else if (ext == ".vert" || ext == ".frag" || ext == ".geom" || ext == ".glsl" || ext == ".tesc" ||
               ext == ".tese") {
      const auto result = app.host->shaders().overrideByName(p);
      app.message = result.error.empty() ? StatusLine::done("now using " + path + " for " + result.replaced)
                                         : StatusLine::failed(path + ": " + result.error);
    } else if (ext == ".json") {
      app.message = loadPreset(*app.host, path);
    } else if (ext == ".png" || ext == ".jpg" || ext == ".jpeg" || ext == ".tga" || ext == ".bmp") {
      const std::string err = app.host->setHeightMap(path);
      app.message = StatusLine::of(err, "height map of the scene's materials: " + path);
    } else if (!app.fileParamUnderMouse.empty()) {
      const std::string key = std::string(app.host->lab().id()) + "." + app.fileParamUnderMouse;
      const std::string err = app.host->set(key + "=" + path);
      app.message = StatusLine::of(err, key + " = " + path);
    } else {
      const std::string err = app.host->selectScene(path);
      app.message = StatusLine::of(err, "loaded scene " + path);
    }
  }
  app.dropped.clear();
}

void viewportControls(AppState& app) {
  ImGuiIO& io = ImGui::GetIO();
  OrbitCamera& cam = app.host->camera();
  if (ImGui::IsItemActive() && ImGui::IsMouseDragging(ImGuiMouseButton_Left))
    cam.orbit(-io.MouseDelta.x * 0.3f, io.MouseDelta.y * 0.3f);
  if (ImGui::IsItemActive() &&
      (ImGui::IsMouseDragging(ImGuiMouseButton_Right) || ImGui::IsMouseDragging(ImGuiMouseButton_Middle)))
    cam.pan(io.MouseDelta.x / float(app.viewport.y), io.MouseDelta.y / float(app.viewport.y));
  if (ImGui::IsItemHovered() && io.MouseWheel != 0.0f) cam.zoom(std::pow(0.9f, io.MouseWheel));
  // I over the viewport: the exercised function traced at that pixel (the Exercises section shows it).
  if (std::exchange(app.inspectKey, false) && ImGui::IsItemHovered() && !io.WantTextInput) {
    const ImVec2 origin = ImGui::GetItemRectMin();
    requestInspection(app.exercises, {int(io.MousePos.x - origin.x), int(io.MousePos.y - origin.y)}, app.viewport);
  }
  // Pixel readout: the float value under the cursor (depth maps, visibility, NaN hunting).
  // Read back without waiting for the frame (PixelProbe): the value shown is a frame or two old.
  if (ImGui::IsItemHovered() && !ImGui::IsItemActive()) {
    const ImVec2 origin = ImGui::GetItemRectMin();
    const int x = int(io.MousePos.x - origin.x), y = int(io.MousePos.y - origin.y);
    app.probe.request(*app.host->target(), x, y);
    if (const auto& v = app.probe.latest())
      ImGui::SetTooltip("pixel %d, %d\nR %.6g  G %.6g\nB %.6g  A %.6g", v->x, v->y, v->rgba[0], v->rgba[1], v->rgba[2],
                        v->rgba[3]);
  }
}

constexpr ImGuiWindowFlags kFixed = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse;
constexpr ImGuiWindowFlags kSidePanel = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse;
// The viewport's window: the lab's frame covers all of it, so it draws no background of its own
// (on a software rasteriser a blended fill of the whole viewport, each frame, under an opaque image).
constexpr ImGuiWindowFlags kViewport = kFixed | ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoBackground;

// The lab's frame filling the current window, and the camera controls over it.
void viewportImage(AppState& app) {
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  app.viewport = glm::max(glm::ivec2(int(avail.x), int(avail.y)), glm::ivec2(16));
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  // The frame is opaque: its alpha is coverage for the metrics (the filtering lab's sky is 0 there),
  // not transparency, so it is drawn without blending, as headless images are written.
  ImDrawList* drawList = ImGui::GetWindowDrawList();
  drawList->AddCallback([](const ImDrawList*, const ImDrawCmd*) { glDisable(GL_BLEND); }, nullptr);
  ImGui::Image(reinterpret_cast<ImTextureID>(intptr_t(app.host->target()->color().id())), avail, {0, 1}, {1, 0});
  drawList->AddCallback(ImDrawCallback_ResetRenderState, nullptr);
  // The inspected point, while the view is the one it was pressed in.
  const ExercisePanel& ex = app.exercises;
  if (!ex.inspection.empty() && ex.inspectViewport == app.viewport && ex.inspectedView == app.host->camera().view()) {
    const ImVec2 at{origin.x + float(ex.inspectPixel.x) + 0.5f, origin.y + float(ex.inspectPixel.y) + 0.5f};
    drawList->AddCircle(at, 7.0f, IM_COL32(0, 0, 0, 255), 16, 3.0f);
    drawList->AddCircle(at, 7.0f, IM_COL32(255, 153, 77, 255), 16, 1.5f);
  }
  ImGui::SetCursorScreenPos(origin);
  ImGui::InvisibleButton(
      "viewport", avail,
      ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight | ImGuiButtonFlags_MouseButtonMiddle);
  viewportControls(app);
}

void leftPanel(AppState& app) {
  LabHost& host = *app.host;
  // An exercise open: its section first, where a student finds it without scrolling.
  const bool exerciseFirst = !app.exercises.selected.empty();
  if (exerciseFirst) {
    if (ImGui::CollapsingHeader("Exercises", ImGuiTreeNodeFlags_DefaultOpen))
      drawExercisePanel(app.exercises, host, app.editor, app.message);
    ImGui::Separator();
  }
  std::vector<std::string> ids = menuLabIds();
  if (std::find(ids.begin(), ids.end(), host.lab().id()) == ids.end())
    ids.emplace_back(host.lab().id());  // --lab minimal
  int current = 0;
  for (size_t i = 0; i < ids.size(); ++i)
    if (ids[i] == host.lab().id()) current = int(i);
  int next = current;
  if (ImGui::ArrowButton("##prev", ImGuiDir_Left)) next = (current + int(ids.size()) - 1) % int(ids.size());
  ImGui::SameLine();
  ImGui::SetNextItemWidth(-40);
  if (ImGui::BeginCombo("##lab", std::string(host.lab().title()).c_str())) {
    for (size_t i = 0; i < ids.size(); ++i)
      if (ImGui::Selectable(ids[i].c_str(), int(i) == current)) next = int(i);
    ImGui::EndCombo();
  }
  ImGui::SameLine();
  if (ImGui::ArrowButton("##next", ImGuiDir_Right)) next = (current + 1) % int(ids.size());
  if (next != current) {
    const std::string err = host.selectLab(ids[size_t(next)]);
    app.message = StatusLine::failed(err);
  }
  ImGui::TextWrapped("%s", std::string(host.lab().summary()).c_str());

  ImGui::Separator();
  const bool listOpened = ImGui::BeginCombo("Scene", host.sceneId().c_str());
  if (listOpened || app.missingData == "?") {
    app.missingData.clear();
    for (auto& id : missingDataScenes()) app.missingData += (app.missingData.empty() ? "" : ", ") + id;
  }
  if (listOpened) {
    for (auto& s : listScenes(host.lab().scenes()))
      if (ImGui::Selectable(s.id.c_str(), s.id == host.sceneId())) {
        const std::string err = host.selectScene(s.id);
        app.message = StatusLine::failed(err);
      }
    ImGui::EndCombo();
  }
  ImGui::PushTextWrapPos(0.0f);
  ImGui::TextDisabled("Or drop a .gltf/.glb/.obj/.off/.ply file on the window (an image: the scene's height map).");
  if (!app.missingData.empty()) ImGui::TextDisabled("Not here: %s. %s", app.missingData.c_str(), missingDataAdvice());
  ImGui::PopTextWrapPos();
  ImGui::Separator();
  drawParamWidgets(host.lab(), &app.fileParamUnderMouse);
  for (auto& e : host.jobs().takeErrors()) app.message = StatusLine::failed(e);
  if (ImGui::Button("Reset parameters")) host.resetParams();
  ImGui::SameLine();
  if (ImGui::Button("Reset view")) host.resetCamera();
  ImGui::Separator();
  if (ImGui::Button("Present (F11)")) app.presenting = true;
  ImGui::SameLine();
  ImGui::SetNextItemWidth(120 * app.uiScale);
  ImGui::SliderFloat("UI scale", &app.uiScale, 0.5f, 4.0f, "%.2f");
  if (ImGui::IsItemDeactivatedAfterEdit()) app.uiScale = std::clamp(app.uiScale, 0.5f, 4.0f);
  if (ImGui::Button("Screenshot (F12)")) app.screenshotRequested = true;
  ImGui::SameLine();
  if (ImGui::Button("Save preset")) app.message = savePreset(host);
  ImGui::SameLine();
  if (ImGui::Button("Copy link")) {
    ShareLink link = shareLink(host);
    addExercise(link, app.exercises.selected, exerciseRootOf(app.exercises.selected), app.siteExerciseRoots,
                app.linkCourse);
    app.message =
        StatusLine::done("copied " + copyLink(link.fragment) + (link.note.empty() ? "" : " (" + link.note + ")"));
  }
  if (ImGui::BeginCombo("Load preset", "choose...")) {
    for (auto& file : listPresets())
      if (ImGui::Selectable(file.c_str())) app.message = loadPreset(host, file);
    ImGui::EndCombo();
  }
  ImGui::Separator();
  if (!exerciseFirst && ImGui::CollapsingHeader("Exercises"))
    drawExercisePanel(app.exercises, host, app.editor, app.message);
}

// One window from its first frame to its last: what the frames share. It lives on the heap, since
// in the browser the page calls drawFrame() long after runWindow has returned.
class WindowSession {
 public:
  WindowSession(GLFWwindow* window, const Options& options, const WindowOptions& wopt);
  // One frame: events, the lab's frame, the UI; false once the window is to close.
  bool drawFrame();
  int exitCode = 0;

 private:
  static ShaderSearchPath shaderPathFor(const Options& options, const SoakDriver* soak) {
    ShaderSearchPath path = shaderSearchPath(options);
    if (soak) path.prepend(soak->scratch());
    return path;
  }

  // When nothing moves (no input, no job, nothing animating, the settings and view unchanged) for
  // kSettleSeconds and kSettleFrames, the window stops drawing and waits for events, waking every
  // kIdleWakeSeconds to pick up saved shader files and finished jobs: an idle window costs next to
  // nothing (a laptop on battery in a lecture hall). Test and soak runs always draw.
  static constexpr double kSettleSeconds = 2.0, kIdleWakeSeconds = 0.25;
  static constexpr int kSettleFrames = 30;
  bool quiet();
  void noteActivity();
  void layoutWindows(glm::ivec2 framebuffer, const std::vector<gl::PassTiming>& passes, float time);
  // Runs one hook of every mode; a mode that ends the run closes the window with its exit code.
  template <typename Hook>
  void runModes(Hook hook) {
    for (auto& mode : modes) {
      hook(*mode);
      if (mode->wantsClose && !glfwWindowShouldClose(window)) {
        exitCode = mode->exitCode;
        glfwSetWindowShouldClose(window, GLFW_TRUE);
      }
    }
  }

  GLFWwindow* window;
  const WindowOptions wopt;
  AppState app;
  // --soak: random use of this window, as `shadelab soak` does headless
  std::unique_ptr<SoakDriver> soak;
  LabHost host;
  Measurer measurer;
  std::chrono::steady_clock::time_point last = std::chrono::steady_clock::now();
  double uiMs = 0;
  std::vector<std::unique_ptr<WindowMode>> modes;  // window_modes.h: what the run does besides drawing
  int frame = 0;
  unsigned seenEvents = 0;
  std::chrono::steady_clock::time_point lastActivity = std::chrono::steady_clock::now();
  int framesSinceActivity = 0;
  bool resumed = false;  // this frame follows a wait: its time since the last frame is no frame time
};

bool WindowSession::quiet() {
  for (auto& mode : modes)
    if (mode->keepsDrawing(app)) return false;
  if (windowEvents() != seenEvents || !app.dropped.empty() || host.jobs().busy() || host.lab().animating() ||
      app.exercises.check.running() || app.exercises.checkRequested || app.exercises.inspectRequested)
    return false;
  const auto still = std::max(lastActivity, app.costs.since);  // the settings, camera and viewport last changed
  return framesSinceActivity >= kSettleFrames &&
         std::chrono::duration<double>(std::chrono::steady_clock::now() - still).count() >= kSettleSeconds;
}

void WindowSession::noteActivity() {
  if (windowEvents() != seenEvents || host.jobs().busy()) {
    seenEvents = windowEvents();
    lastActivity = std::chrono::steady_clock::now();
    framesSinceActivity = 0;
  } else {
    ++framesSinceActivity;
  }
}

WindowSession::WindowSession(GLFWwindow* window, const Options& options, const WindowOptions& wopt)
    : window(window),
      wopt(wopt),
      soak(wopt.soakMinutes > 0 ? std::make_unique<SoakDriver>(SoakDriver::makeScratch(), wopt.soakSeed) : nullptr),
      host(shaderPathFor(options, soak.get())),
      measurer(host),
      modes(windowModes(wopt, soak.get(), labIds())) {
  host.jobs().setLowPriority(true);  // the window's frames come first
  measurer.onMeasured = [](const Measurement& m) {
    std::printf("measured %s (%s), truth: %s:", m.lab.c_str(), m.label.c_str(), m.truth.c_str());
    for (auto& [k, v] : m.values) std::printf(" %s=%s", k.c_str(), formatNumber(v).c_str());
    std::printf("\n");
    std::fflush(stdout);
  };
  app.host = &host;
  app.measurer = &measurer;
  app.measure.autoMeasure = wopt.autoMeasure;
  app.measure.requested = options.measure;  // --measure: press Measure once the first frames are timed
  app.presenting = wopt.present;
  if (!options.shaderDirs.empty())
    app.editor.folder = options.shaderDirs.front();  // edits go to the student's first folder
  if (!wopt.editFolder.empty()) app.editor.folder = wopt.editFolder;
  app.linkCourse = wopt.linkCourse;
  app.siteExerciseRoots = {builtinExercisesRoot()};
  if (!wopt.siteCourse.empty()) app.siteExerciseRoots.push_back(wopt.siteCourse);
  if (wopt.uiScale > 0) {
    app.uiScale = wopt.uiScale;
  } else {  // a high-DPI monitor's content scale, so text is as large as on any other screen
    app.uiScale = std::clamp(contentScale(window), 0.5f, 4.0f);
  }
  glfwSetWindowUserPointer(window, &app);
  glfwSetDropCallback(window, onDrop);
  // What the command line (or the page's link) got wrong, every line of it: a later setting that
  // went well does not wipe out an earlier one that did not.
  const auto note = [&](const std::string& e) {
    if (!e.empty()) app.message = StatusLine::failed(app.message.text + (app.message.empty() ? "" : "\n") + e);
  };
  note(wopt.message);
  // --exercise (the page's link): the exercise's lab on screen with its first configuration, the
  // Exercises section open on it; a --lab, --scene, --set or preset given beside it goes over that.
  if (!options.exercise.empty()) {
    Exercise ex;
    if (auto e = loadExercise(options.exercise, ex); !e.empty())
      note(e);
    else if (const StatusLine opened = openExercise(app.exercises, host, ex.id); opened.problem)
      note(opened.text);
    else
      std::printf("exercise %s opened on the %s lab: %s\n", ex.id.c_str(), ex.lab.c_str(), opened.text.c_str());
  }
  if (!options.preset.empty()) app.message = loadPreset(host, options.preset);  // "loaded ...", or why not
  if (!options.lab.empty() && options.lab != host.lab().id()) note(host.selectLab(options.lab));
  if (!options.scene.empty()) note(host.selectScene(options.scene));
  for (auto& s : options.sets) note(host.set(s));
  for (auto& a : options.actions) note(host.runAction(a));
  note(applyCamera(host, options.camera));
  if (!app.message.empty()) std::fprintf(stderr, "shadelab: %s\n", app.message.text.c_str());
}

// The windows of one frame: the side panels and the viewport, or presentation mode's viewport and
// overlay; the jobs' progress over the viewport.
void WindowSession::layoutWindows(glm::ivec2 framebuffer, const std::vector<gl::PassTiming>& passes, float time) {
  const int fbw = framebuffer.x, fbh = framebuffer.y;
  if (app.presenting) {
    // The viewport fills the window; the overlay carries what the class reads.
    ImGui::SetNextWindowPos({0, 0});
    ImGui::SetNextWindowSize({float(fbw), float(fbh)});
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, {0, 0});
    ImGui::Begin("Viewport", nullptr, kViewport | ImGuiWindowFlags_NoTitleBar);
    viewportImage(app);
    ImGui::End();
    ImGui::PopStyleVar();
    presentationOverlay(app, passes);
  } else {
    // Side panels keep their width and are resized by their inner edge, each at most 35 % of
    // the window, so the viewport always has 30 % or more; it takes the rest.
    const float maxW = 0.35f * float(fbw), minW = std::min(220 * app.uiScale, maxW);
    app.leftW = std::clamp(app.leftW, minW, maxW);
    app.rightW = std::clamp(app.rightW, minW, maxW);
    ImGui::SetNextWindowPos({0, 0});
    ImGui::SetNextWindowSize({app.leftW, float(fbh)});
    ImGui::SetNextWindowSizeConstraints({minW, float(fbh)}, {maxW, float(fbh)});
    ImGui::Begin("Lab", nullptr, kSidePanel);
    leftPanel(app);
    app.leftW = ImGui::GetWindowWidth();
    ImGui::End();

    ImGui::SetNextWindowPos({float(fbw) - app.rightW, 0});
    ImGui::SetNextWindowSize({app.rightW, float(fbh)});
    ImGui::SetNextWindowSizeConstraints({minW, float(fbh)}, {maxW, float(fbh)});
    ImGui::Begin("Inspect", nullptr, kSidePanel);
    if (ImGui::CollapsingHeader("Cost", ImGuiTreeNodeFlags_DefaultOpen)) drawStatsPanel(host, app.history, uiMs);
    if (ImGui::CollapsingHeader("Error against the truth", ImGuiTreeNodeFlags_DefaultOpen)) {
      const MeasureRequest now{
          app.costs.signature,
          std::chrono::duration<double>(std::chrono::steady_clock::now() - app.costs.since).count(), app.costs.costs(),
          app.viewport, time};
      drawMeasurePanel(host, measurer, app.measure, now, app.message);
    }
    drawLabPanels(host.lab());
    if (app.exercises.selected.empty() && !app.exercises.inspection.empty() &&
        ImGui::CollapsingHeader("At the pixel (I over the view)", ImGuiTreeNodeFlags_DefaultOpen))
      drawInspection(app.exercises);
    if (ImGui::CollapsingHeader("Messages", ImGuiTreeNodeFlags_DefaultOpen)) drawWarnings(host, app.message);
    if (ImGui::CollapsingHeader("Shaders", ImGuiTreeNodeFlags_DefaultOpen)) {
      drawShaderPanel(host, app.message);
      drawEditableFiles(app.editor, host);
    }
    app.rightW = ImGui::GetWindowWidth();
    ImGui::End();

    const float viewW = std::max(float(fbw) - app.leftW - app.rightW, 16.0f);
    ImGui::SetNextWindowPos({app.leftW, 0});
    ImGui::SetNextWindowSize({viewW, float(fbh)});
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, {0, 0});
    ImGui::Begin("Viewport", nullptr, kViewport);
    viewportImage(app);
    ImGui::End();
    ImGui::PopStyleVar();

    // Running jobs over the bottom of the viewport: progress, what they do, Cancel.
    if (host.jobs().busy()) {
      ImGui::SetNextWindowPos({app.leftW + 10, float(fbh) - 10}, ImGuiCond_Always, {0, 1});
      ImGui::SetNextWindowSize({viewW - 20, 0});
      ImGui::SetNextWindowBgAlpha(0.85f);
      ImGui::Begin("Jobs", nullptr,
                   ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                       ImGuiWindowFlags_NoFocusOnAppearing);
      drawJobs(host.jobs());
      ImGui::End();
    }
  }
}

bool WindowSession::drawFrame() {
  if (glfwWindowShouldClose(window)) return false;
  // 1. events; when nothing moves, wait for them instead of drawing the same frame again
  if (quiet()) {
    waitForEvents(kIdleWakeSeconds);
    if (windowEvents() == seenEvents && !host.pollChanges()) {
      resumed = true;
      return !glfwWindowShouldClose(window);
    }
    lastActivity = std::chrono::steady_clock::now();  // a saved shader or a finished job: draw a while
    framesSinceActivity = 0;
  } else {
    glfwPollEvents();
  }
  noteActivity();
  handleDrops(app);
  const auto now = std::chrono::steady_clock::now();
  // After a wait the time since the last drawn frame is idle time, not frame time: one refresh.
  const float dt = resumed ? 1.0f / 60.0f : std::chrono::duration<float>(now - last).count();
  last = now;
  FrameEvent event{host, app, frame, dt * 1000.0f, 0.0};
  runModes([&](WindowMode& m) { m.beforeLabFrame(event); });
  // A Check draws its configurations between frames, one a frame, in this context.
  stepExerciseCheck(app.exercises, host, app.message);

  // 2. the lab's frame (at the viewport size the last layout gave it)
  const float time = float(glfwGetTime());
  const auto& passes = host.renderFrame(app.viewport, time, dt);
  measurer.followLab();  // after a lab switch, the last lab's truths and images go now
  for (auto& p : passes) event.labGpuMs += p.gpuMs;
  runModes([&](WindowMode& m) { m.afterLabFrame(event); });
  if (!resumed) app.history.push(dt * 1000.0f, float(event.labGpuMs));
  resumed = false;
  app.costs.push(host.stateJson().dump() + std::to_string(app.viewport.x) + "x" + std::to_string(app.viewport.y),
                 passes);

  // 3. UI layout
  const auto uiStart = std::chrono::steady_clock::now();
  applyUiScale(app);
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  int fbw = 0, fbh = 0;
  glfwGetFramebufferSize(window, &fbw, &fbh);
  layoutWindows({fbw, fbh}, passes, time);
  drawShaderEditor(app.editor, host, app.message);

  // 4. draw the UI
  ImGui::Render();
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, fbw, fbh);
  if (!app.presenting) {  // presenting, the lab's frame covers the whole window: nothing to clear
    glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
  }
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  uiMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - uiStart).count();

  runModes([&](WindowMode& m) { m.afterUi(event, {fbw, fbh}); });
  glfwSwapBuffers(window);
  ++frame;
  return !glfwWindowShouldClose(window);
}

}  // namespace

int runWindow(const Options& options, const WindowOptions& wopt) {
  glfwSetErrorCallback([](int, const char* d) { std::fprintf(stderr, "glfw: %s\n", d); });
  if (!glfwInit()) return 2;
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  GLFWwindow* window = nullptr;
  for (const gl::Version v : gl::kContextVersions) {
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, v.major);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, v.minor);
    if ((window = glfwCreateWindow(wopt.size.x, wopt.size.y, "ShadeLab", nullptr, nullptr))) break;
  }
  if (!window) {
    glfwTerminate();
    return 2;
  }
  glfwMakeContextCurrent(window);
  enableContextFeatures();
  followPageSize(window);
  glfwSwapInterval(1);
  const char* missing = "";
  if (!gl::loadFunctions(glProcLoader(), &missing)) {
    std::fprintf(stderr, "shadelab: the window's OpenGL context lacks %s\n", missing);
    return 1;
  }

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // the layout is fixed; write nothing into the user's folder
  ImGui::StyleColorsDark();
  glfwSetKeyCallback(window, onKey);
  countInput(window);
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  countWindowChanges(window);
  ImGui_ImplOpenGL3_Init(imguiGlslVersion());

  auto session = std::make_shared<WindowSession>(window, options, wopt);
  runMainLoop([session] { return session->drawFrame(); });
  const int exitCode = session->exitCode;
  session.reset();
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window);
  glfwTerminate();
  return exitCode;
}

}  // namespace shadelab

// What the window's panels, its frame and its modes share.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "app/gl/pixel_probe.h"
#include "app/host/share_link.h"
#include "app/ui/exercise_panel.h"
#include "app/ui/frame_records.h"
#include "app/ui/panels.h"
#include "app/ui/shader_editor.h"

namespace shadelab {

class LabHost;
class Measurer;

struct AppState {
  LabHost* host = nullptr;
  Measurer* measurer = nullptr;
  StatusLine message;  // what the last action did, or why it could not (the Messages panel)
  std::vector<std::string> dropped;
  std::string fileParamUnderMouse;  // a file parameter's key, as of the last frame: drops go there
  // Data scenes not downloaded ("?": not looked up yet): looked up at start and while the scene
  // list is open, not every frame.
  std::string missingData = "?";
  glm::ivec2 viewport{960, 600};
  FrameHistory history;
  ConfigurationCosts costs;
  MeasureUi measure;
  ShaderEditor editor;
  ExercisePanel exercises;
  // Where a link can find an exercise: the page's link course, and the folders every page of the
  // site lists (the built-in exercises; in the page, the course the site was built with).
  LinkCourse linkCourse;
  std::vector<std::filesystem::path> siteExerciseRoots;
  PixelProbe probe;  // the viewport's readout under the cursor
  Responsiveness responsiveness;
  bool screenshotRequested = false;
  bool inspectKey = false;  // I pressed since the viewport last looked
  // The layout: side panels the user widens or narrows by their inner edge, or presentation mode
  // (F11) with the viewport filling the window for a projector; everything scaled by uiScale.
  float leftW = 380, rightW = 380;
  bool presenting = false;
  float uiScale = 1.0f, appliedScale = 0.0f;
};

}  // namespace shadelab

// Dear ImGui panels of the window front end. Each draws one concern and changes state only
// through the host (the same write path as the CLI and presets).
#pragma once
#include <deque>
#include <string>

#include "app/host/lab_host.h"
#include "app/host/measurer.h"
#include "app/ui/status_line.h"

namespace shadelab {

// Widgets for a lab's parameter list; returns true when any value changed. `fileUnderMouse`, when
// given, receives the key of the file parameter the mouse is over ("" if none): a file dropped
// on the window then goes to that parameter rather than becoming the scene.
bool drawParamWidgets(Lab& lab, std::string* fileUnderMouse = nullptr);

struct FrameHistory {
  std::deque<float> frameMs;  // wall time between frames
  std::deque<float> gpuMs;    // summed pass time
  void push(float frame, float gpu);
};
void drawStatsPanel(const LabHost& host, const FrameHistory& history, double uiMs);

// Active programs with their status; a failed build shows file:line:col, the source line and a
// caret under the column. `status` receives messages such as "reloaded 2 programs".
void drawShaderPanel(LabHost& host, StatusLine& status);

void drawWarnings(const LabHost& host, const StatusLine& last);

// The lab's own panels (app/lab/lab_panel.h).
void drawLabPanels(const Lab& lab);
// A progress bar with Cancel per running job; returns whether any runs.
bool drawJobs(JobRunner& jobs);

// What the window knows about the configuration on screen, for measuring it.
struct MeasureRequest {
  std::string signature;    // settings + camera + size: a change means "not measured yet"
  double stillSeconds = 0;  // since the signature last changed
  Metrics costs;            // gpu_ms and cpu_ms medians of this configuration's recent frames
  glm::ivec2 size{0};
  float time = 0;
};
struct MeasureUi {
  bool autoMeasure = false;
  bool requested = false;         // the Measure button, or --measure on the command line
  std::string measuredSignature;  // what the last measurement was started for
  int plot = 0;                   // which of the lab's plots is shown
};
void drawMeasurePanel(LabHost& host, Measurer& measurer, MeasureUi& ui, const MeasureRequest& now, StatusLine& message);

}  // namespace shadelab
